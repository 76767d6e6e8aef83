// The `clip_sequence` target (decoders.hpp): continuous clipping of one evolving set, every
// state checked, the recorded log replayed, and now and then the validating clip() on operands
// that may be invalid.
#include <exception>
#include <utility>

#include "clip_decoding.hpp"
#include "clip_references.hpp"
#include "decoders.hpp"
#include "edgeland/io/clip_log.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::fuzz {
namespace {

constexpr std::size_t kMaxStateVertices = 400;  // a sequence stops growing past this
constexpr std::size_t kMaxSteps = 12;

// The validating clip() (PolygonSet operands, which may be invalid here): InvalidInput exactly
// when validate() rejects an operand, naming the subject first and carrying validate()'s own
// first violation; otherwise exactly the ValidSet overload's result (clip/README.md,
// "Validating while clipping").
std::optional<Finding> validating_clip_agrees(ClipOp op, const PolygonSet& a, const PolygonSet& b,
                                              const Text& log) {
  const ValidationReport va = validate(a, 1), vb = validate(b, 1);
  const Text line = [&] { return op_line(op, a, b); };
  try {
    const ClipResult r = clip(op, a, b, ClipOptions{.checked = true});
    if (!va.ok() || !vb.ok()) {
      return Finding{"clip() accepted an invalid operand (" +
                         (va.ok() ? vb : va).violations.front().describe() + "): " + line(),
                     log()};
    }
    const ValidClipResult v =
        clip(op, ValidSet(a), ValidSet(b, Operand::kClip), ClipOptions{.checked = true});
    if (v.set.polygons() != r.polygons)
      return Finding{"clip() on PolygonSets and on ValidSets differ: " + line(), log()};
  } catch (const InvalidInput& e) {
    if (va.ok() && vb.ok())
      return Finding{std::string("InvalidInput on valid operands: ") + e.what() + "\n  " + line(),
                     log()};
    const Operand which = va.ok() ? Operand::kClip : Operand::kSubject;
    const Violation& expected = (va.ok() ? vb : va).violations.front();
    if (e.operand != which || e.violation.describe() != expected.describe()) {
      return Finding{std::string("clip() reports ") + e.what() + " where validate() finds " +
                         (va.ok() ? "clip: " : "subject: ") + expected.describe() + "\n  " + line(),
                     log()};
    }
  } catch (const InternalError& e) {
    return Finding{std::string("InternalError: ") + e.what() + "\n  " + line(), log()};
  } catch (const std::exception& e) {
    return Finding{std::string("unexpected exception: ") + e.what() + "\n  " + line(), log()};
  }
  return std::nullopt;
}

// One sequence as it runs: the decoding, the evolving set and the recording of its steps.
// Every finding carries the log recorded up to it.
class Sequence {
 public:
  Sequence(const std::uint8_t* data, std::size_t size)
      : in_(data, size), decoder_(in_), state_(decoder_.valid_set()) {
    recorder_.record_set(state_.current());
  }
  // The steps, then the replay of the log: the first finding, if any.
  std::optional<Finding> run();
  const std::string& log() const { return recorder_.text(); }

 private:
  std::optional<Finding> step(std::size_t s);
  PolygonSet raw_operand();
  std::optional<Finding> probe_validating_clip(std::size_t s, ClipOp op, const PolygonSet& before,
                                               const PolygonSet& operand, bool raw) const;
  std::optional<Finding> apply(ClipOp op, const PolygonSet& before, const PolygonSet& operand);
  std::optional<Finding> rejected(const InvalidInput& e, const PolygonSet& before,
                                  const PolygonSet& operand, const Text& context) const;
  std::optional<Finding> replay_differs() const;

  Provider in_;
  Decoder decoder_;
  log::EditLog recorder_;
  log::EvolvingSet state_;
};

std::optional<Finding> Sequence::run() {
  const std::size_t steps = in_.ConsumeIntegralInRange<std::size_t>(1, kMaxSteps);
  for (std::size_t s = 0; s < steps && in_.remaining_bytes() > 0; ++s) {
    if (vertex_count(state_.current()) > kMaxStateVertices) break;
    if (auto f = step(s)) return f;
  }
  return replay_differs();
}

// One step: an operand drawn near the current state (one in 8 raw rings, possibly invalid).
std::optional<Finding> Sequence::step(std::size_t s) {
  decoder_.absorb(state_.current());
  const ClipOp op = in_.PickValueInArray(kOps);
  const bool raw = in_.ConsumeIntegralInRange(0, 7) == 0;
  const PolygonSet operand = raw ? raw_operand() : decoder_.valid_set();
  const PolygonSet before = state_.current();
  if (auto f = probe_validating_clip(s, op, before, operand, raw)) return f;
  return apply(op, before, operand);
}

PolygonSet Sequence::raw_operand() {
  PolygonSet operand;
  for (Ring& ring : decoder_.raw_rings(false)) operand.push_back(std::move(ring));
  return operand;
}

// Now and then the validating clip() on operands that may be invalid: the raw operand, or
// the state and the operand merged into one set (members overlapping, nested, sharing
// edges in one direction, or a valid set after all). Chosen from what is already decoded,
// consuming no input: saved inputs keep decoding to the cases they were saved for.
std::optional<Finding> Sequence::probe_validating_clip(std::size_t s, ClipOp op,
                                                       const PolygonSet& before,
                                                       const PolygonSet& operand, bool raw) const {
  const Text log_so_far = [&] { return recorder_.text(); };
  switch ((s + before.size() + 3 * operand.size()) % 4) {
    case 0: {
      PolygonSet merged = before;
      merged.insert(merged.end(), operand.begin(), operand.end());
      const bool merged_first = (s / 4) % 2 == 0;
      return validating_clip_agrees(op, merged_first ? merged : operand,
                                    merged_first ? operand : merged, log_so_far);
    }
    case 1:
      if (raw) return validating_clip_agrees(op, operand, before, log_so_far);
      return std::nullopt;
    default:
      return std::nullopt;
  }
}

// Applies the step and records it; a finding when it fails other than by a rightful
// InvalidInput, or leaves an invalid state.
std::optional<Finding> Sequence::apply(ClipOp op, const PolygonSet& before,
                                       const PolygonSet& operand) {
  const Text context = [&] { return op_line(op, before, operand); };
  try {
    state_.apply(op, operand, ClipOptions{.checked = true});
  } catch (const InvalidInput& e) {
    return rejected(e, before, operand, context);
  } catch (const InternalError& e) {
    recorder_.comment(std::string("the next step failed: ") + e.what());
    recorder_.record_clip(op, before, operand, before);
    return Finding{std::string("InternalError: ") + e.what() + "\n  " + context(),
                   recorder_.text()};
  }
  recorder_.record_clip(op, before, operand, state_.current());
  return invalid_output(context, state_.current(), [&] { return recorder_.text(); });
}

// A step rejected with InvalidInput leaves the set unchanged, and only an invalid clip operand
// may be the reason.
std::optional<Finding> Sequence::rejected(const InvalidInput& e, const PolygonSet& before,
                                          const PolygonSet& operand, const Text& context) const {
  if (state_.current() != before)
    return Finding{"a step rejected with InvalidInput changed the set: " + context(),
                   recorder_.text()};
  if (e.operand != Operand::kClip || validate(operand, 0).ok())
    return Finding{std::string("InvalidInput (") + e.what() +
                       ") for a step whose only bad operand could be the clip one: " + context(),
                   recorder_.text()};
  return std::nullopt;
}

// The recorded log must replay to the same state (recorder, parser and determinism).
std::optional<Finding> Sequence::replay_differs() const {
  const log::ParsedLog parsed = log::parse_log(recorder_.text());
  if (parsed.error)
    return Finding{std::string("recorded log does not parse: ") + parsed.error->what(),
                   recorder_.text()};
  log::EvolvingSet replayed;
  for (const log::Step& step : parsed.steps) replayed.apply(step);
  if (replayed.current() != state_.current())
    return Finding{"replaying the recorded log gives another state:\n  live = " +
                       to_wkt(state_.current()) + "\n  replay = " + to_wkt(replayed.current()),
                   recorder_.text()};
  return std::nullopt;
}

}  // namespace

std::optional<Finding> run_clip_sequence(const std::uint8_t* data, std::size_t size) {
  try {
    return Sequence(data, size).run();
  } catch (const std::exception& e) {
    return Finding{std::string("unexpected exception: ") + e.what(), ""};
  }
}

std::string clip_sequence_log(const std::uint8_t* data, std::size_t size) {
  Sequence sequence(data, size);
  sequence.run();
  return sequence.log();
}

}  // namespace edgeland::fuzz
