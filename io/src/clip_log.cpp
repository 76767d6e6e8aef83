#include "edgeland/io/clip_log.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "log_text.hpp"

namespace edgeland::log {
namespace {

constexpr std::array<StepKind, 5> kAllSteps{StepKind::kSet, StepKind::kUnion,
                                            StepKind::kIntersection, StepKind::kDifference,
                                            StepKind::kXor};

ClipOp op_of(StepKind kind) {
  switch (kind) {
    case StepKind::kUnion:
      return ClipOp::kUnion;
    case StepKind::kIntersection:
      return ClipOp::kIntersection;
    case StepKind::kDifference:
      return ClipOp::kDifference;
    case StepKind::kXor:
    case StepKind::kSet:
      break;
  }
  return ClipOp::kXor;
}

}  // namespace

// The operations' keywords are the library's own names (op_name): one table of them.
const char* step_keyword(StepKind kind) noexcept {
  return kind == StepKind::kSet ? "set" : op_name(op_of(kind));
}

StepKind step_kind(ClipOp op) noexcept {
  switch (op) {
    case ClipOp::kUnion:
      return StepKind::kUnion;
    case ClipOp::kIntersection:
      return StepKind::kIntersection;
    case ClipOp::kDifference:
      return StepKind::kDifference;
    case ClipOp::kXor:
      break;
  }
  return StepKind::kXor;
}

const char* log_error_kind_name(LogErrorKind kind) noexcept {
  switch (kind) {
    case LogErrorKind::kUnknownStep:
      return "unknown-step";
    case LogErrorKind::kMissingShape:
      return "missing-shape";
    case LogErrorKind::kBadShape:
      return "bad-shape";
  }
  return "?";
}

LogError::LogError(LogErrorKind kind_, std::size_t line_, const std::string& reason,
                   std::size_t column_)
    : Error(line_place(line_, column_) + ": " + reason),
      kind(kind_),
      line(line_),
      column(column_) {}

std::optional<Step> parse_log_line(std::string_view raw, std::size_t line_number) {
  std::string_view rest = trim_blanks(raw);
  if (is_skipped_line(rest)) return std::nullopt;
  const std::string_view word = take_word(rest);
  const auto kind = std::find_if(kAllSteps.begin(), kAllSteps.end(),
                                 [&](StepKind k) { return word == step_keyword(k); });
  if (kind == kAllSteps.end()) {
    throw LogError(LogErrorKind::kUnknownStep, line_number,
                   "unknown step '" + printable_excerpt(word) +
                       "' (expected set, union, intersection, difference or xor)");
  }
  const std::string_view wkt = rest;
  if (wkt.empty()) {
    throw LogError(LogErrorKind::kMissingShape, line_number,
                   std::string(step_keyword(*kind)) + ": missing WKT shape");
  }
  Step step;
  step.kind = *kind;
  step.line = line_number;
  try {
    step.shape = read_wkt(wkt);
  } catch (const WktError& error) {
    const ShapeError where = shape_error(raw, wkt, error);
    LogError log_error(LogErrorKind::kBadShape, line_number,
                       std::string(step_keyword(*kind)) + ": " + where.reason, where.column);
    log_error.wkt_error = error.kind;
    throw log_error;
  }
  return step;
}

ParsedLog parse_log(std::string_view text) {
  ParsedLog parsed;
  std::size_t line_number = 0;
  while (!text.empty()) {
    ++line_number;
    const std::string_view line = take_line(text);
    try {
      if (std::optional<Step> step = parse_log_line(line, line_number)) {
        parsed.steps.push_back(std::move(*step));
      }
    } catch (const LogError& error) {
      parsed.error = error;
      break;
    }
  }
  return parsed;
}

PolygonSet shape_to_set(const WktGeometry& shape, const ClipOptions& options) {
  bool hole_free = true;
  PolygonSet exteriors;
  std::vector<std::vector<Ring>> polygons;
  polygons.reserve(shape.polygons.size());
  for (const WktPolygon& polygon : shape.polygons) {
    hole_free = hole_free && polygon.holes.empty();
    exteriors.push_back(polygon.exterior);
    std::vector<Ring> rings{polygon.exterior};
    rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
    polygons.push_back(std::move(rings));
  }
  // A recorded state is already valid: keep it vertex for vertex (same region either way).
  if (hole_free && validate(exteriors, 0).ok()) return exteriors;
  return import_polygons(polygons, options).polygons;
}

void EvolvingSet::apply(const Step& step, const ClipOptions& options) {
  PolygonSet operand = shape_to_set(step.shape, options);
  if (step.kind == StepKind::kSet) {
    current_ = ValidSet(std::move(operand));
    return;
  }
  apply(op_of(step.kind), operand, options);
}

ClipStats EvolvingSet::apply(ClipOp op, const PolygonSet& operand, const ClipOptions& options) {
  ValidClipResult result =
      clip(op, current_, ValidSet(operand, Operand::kClip), options);  // throws before any change
  current_ = std::move(result.set);
  return result.stats;
}

void EditLog::comment(std::string_view comment_text) {
  text_ += "# ";
  for (const char c : comment_text) text_ += (c == '\n' || c == '\r') ? ' ' : c;
  text_ += '\n';
}

void EditLog::write_step(StepKind kind, const PolygonSet& shape) {
  text_ += step_keyword(kind);
  text_ += ' ';
  text_ += to_wkt(shape);
  text_ += '\n';
  ++steps_;
}

void EditLog::record_set(const PolygonSet& set) {
  write_step(StepKind::kSet, set);
  state_ = set;
}

void EditLog::record_clip(ClipOp op, const PolygonSet& subject, const PolygonSet& operand,
                          const PolygonSet& result) {
  if (!state_ || *state_ != subject) write_step(StepKind::kSet, subject);
  write_step(step_kind(op), operand);
  state_ = result;
}

ClipResult EditLog::clip(ClipOp op, const PolygonSet& subject, const PolygonSet& operand,
                         const ClipOptions& options) {
  try {
    ClipResult result = edgeland::clip(op, subject, operand, options);
    record_clip(op, subject, operand, result.polygons);
    return result;
  } catch (const InternalError& error) {
    comment(std::string("the next step failed: ") + error.what());
    if (!state_ || *state_ != subject) write_step(StepKind::kSet, subject);
    write_step(step_kind(op), operand);
    state_.reset();
    throw;
  }
}

std::string fnv1a64_hex(std::string_view text) {
  std::uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a 64 offset basis
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ull;  // FNV-1a 64 prime
  }
  return hex16(hash);
}

std::string state_hash(const PolygonSet& set) { return fnv1a64_hex(to_wkt(set)); }

}  // namespace edgeland::log
