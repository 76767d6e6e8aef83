// The replay of a landscape log (landscape_replay.hpp): parse, build the world, apply the edits
// until one fails, check at the end when asked; then the report as JSON.
#include "edgeland/io/landscape_replay.hpp"

#include "edgeland/clip/errors.hpp"
#include "edgeland/io/landscape_log.hpp"
#include "json_text.hpp"
#include "log_text.hpp"

namespace edgeland::log {
namespace {

using Kind = ReplayFailure::Kind;

// An error's text on one line: internal errors carry the operands' WKT on lines of their own.
std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

ReplayFailure edit_failure(const LandscapeEdit& edit, const std::string& what, Kind kind) {
  const std::string keyword =
      edit.batch > 0 ? std::string(kBatchKeyword) : landscape_edit_keyword(edit.kind);
  const std::string prefix = "line " + std::to_string(edit.line) + ": " + keyword + ": ";
  return {kind, edit.line,
          prefix + (kind == Kind::kInternal ? "internal error: " : "") + one_line(what)};
}

// One step (an edit line, or a batch line's edits); the failure if it throws. A shape the
// kernel refuses is the log's fault; an internal error of the landscape or of the OGC import is
// edgeland's.
std::optional<ReplayFailure> apply_one(Landscape& landscape, std::span<const LandscapeEdit> step) {
  const LandscapeEdit& edit = step.front();
  try {
    apply_step(landscape, step);
  } catch (const LandscapeInternalError& error) {
    return edit_failure(edit, error.what(), Kind::kInternal);
  } catch (const InternalError& error) {
    return edit_failure(
        edit,
        std::string(error.what()) + "; subject " + error.subject_wkt + "; clip " + error.clip_wkt,
        Kind::kInternal);
  } catch (const Error& error) {
    return edit_failure(edit, error.what(), Kind::kUnreadable);
  }
  return std::nullopt;
}

// The edits in order until one throws; the time they took.
void apply_edits(LandscapeReplay& replay, const std::vector<LandscapeEdit>& edits) {
  const auto start = std::chrono::steady_clock::now();
  const std::span<const LandscapeEdit> all(edits);
  for (std::size_t i = 0; i < all.size();) {
    const std::span<const LandscapeEdit> step = all.subspan(i, step_size(all.subspan(i)));
    replay.failure = apply_one(*replay.landscape, step);
    if (replay.failure) break;
    replay.edits += step.size();
    i += step.size();
  }
  replay.edit_time = std::chrono::steady_clock::now() - start;
}

// With --check: every invariant over the whole world (Landscape::check).
std::optional<ReplayFailure> final_check(const Landscape& landscape) {
  const LandscapeReport report = landscape.check();
  if (report.ok()) return std::nullopt;
  return ReplayFailure{Kind::kInternal, 0,
                       "internal error: check() found " + std::to_string(report.problems.size()) +
                           " problem(s), the first: " + one_line(report.problems.front())};
}

// Edits per second as an integer, from the nanoseconds they took (0 when too quick to time).
std::int64_t edits_per_second(const LandscapeReplay& replay) {
  const std::int64_t ns = replay.edit_time.count();
  if (ns <= 0) return 0;
  return static_cast<std::int64_t>(static_cast<Int128>(replay.edits) * 1000000000 / ns);
}

void append_field(std::string& out, std::string_view name, const std::string& json_value) {
  if (out.size() > 1) out += ',';
  out.append(json_string(name)).append(":").append(json_value);
}

void append_world(std::string& out, const LandscapeReplay& replay) {
  const Landscape& l = *replay.landscape;
  const LandscapeStats stats = l.stats();
  append_field(out, "polygons", std::to_string(stats.polygons));
  append_field(out, "vertices", std::to_string(stats.vertices));
  append_field(out, "cells", std::to_string(stats.cells));
  append_field(out, "depth", std::to_string(stats.depth));
  std::string areas = "{";
  for (const auto& [material, twice] : material_areas(l)) {
    append_field(areas, to_string(material), json_string(to_string(twice)));
  }
  append_field(out, "area", areas + "}");
  append_field(out, "state_hash", json_string(state_hash_hex(l.state_hash())));
  append_field(out, "edits_per_second", std::to_string(edits_per_second(replay)));
}

}  // namespace

LandscapeReplay replay_landscape_log(std::string_view text, const LandscapeReplayOptions& options) {
  LandscapeReplay replay;
  const ParsedLandscapeLog parsed = parse_landscape_log(text);
  if (!parsed.world) {
    replay.failure = ReplayFailure{Kind::kUnreadable, parsed.error->line, parsed.error->what()};
    return replay;
  }
  replay.landscape = make_landscape(*parsed.world);
  replay.landscape->set_checked(options.check);
  if (options.record_log) replay.landscape->start_log();
  apply_edits(replay, parsed.edits);
  if (!replay.failure && parsed.error) {
    replay.failure = ReplayFailure{Kind::kUnreadable, parsed.error->line, parsed.error->what()};
  }
  if (options.check && (!replay.failure || replay.failure->kind != Kind::kInternal)) {
    if (std::optional<ReplayFailure> broken = final_check(*replay.landscape)) {
      replay.failure = std::move(broken);
    }
  }
  return replay;
}

std::string replay_json(const LandscapeReplay& replay) {
  std::string out = "{";
  append_field(out, "edits", std::to_string(replay.edits));
  if (replay.landscape) append_world(out, replay);
  if (const std::optional<ReplayFailure>& failure = replay.failure) {
    if (failure->line != 0) append_field(out, "stopped_at_line", std::to_string(failure->line));
    append_field(out, "error", json_string(failure->message));
  }
  return out + "}";
}

std::string state_hash_hex(std::uint64_t hash) { return hex16(hash); }

std::vector<std::pair<Material, Int128>> material_areas(const Landscape& landscape) {
  std::vector<std::pair<Material, Int128>> out;
  for (std::size_t m = 0; m < kMaterialCount; ++m) {
    const Int128 twice = landscape.twice_area(m);
    if (twice != 0) out.emplace_back(m, twice);
  }
  return out;
}

}  // namespace edgeland::log
