#include "landscape_replay.hpp"

#include <chrono>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "command.hpp"
#include "edgeland/clip/clip.hpp"
#include "landscape_dump.hpp"
#include "landscape_log.hpp"
#include "landscape_png.hpp"
#include "landscape_report.hpp"

namespace edgeland::cli {
namespace {

using Failure = ReplayFailure;

// An error's text on one line: internal errors carry the operands' WKT on lines of their own.
std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

Failure edit_failure(const log::LandscapeEdit& edit, const std::string& what, int status) {
  const std::string prefix =
      "line " + std::to_string(edit.line) + ": " + log::landscape_edit_keyword(edit.kind) + ": ";
  return {edit.line, prefix + (status == kExitInternal ? "internal error: " : "") + one_line(what),
          status};
}

// The edits of the log in order until one throws. A shape the kernel refuses is the log's
// fault (exit 2); an internal error of the landscape or of the import is edgeland's (exit 3).
struct Applied {
  std::size_t edits = 0;
  double seconds = 0;
  std::optional<Failure> failure;
};

Applied apply_edits(Landscape& landscape, const std::vector<log::LandscapeEdit>& edits) {
  Applied out;
  const auto start = std::chrono::steady_clock::now();
  for (const log::LandscapeEdit& edit : edits) {
    try {
      log::apply_edit(landscape, edit);
      ++out.edits;
    } catch (const LandscapeInternalError& error) {
      out.failure = edit_failure(edit, error.what(), kExitInternal);
    } catch (const InternalError& error) {
      out.failure = edit_failure(
          edit,
          std::string(error.what()) + "; subject " + error.subject_wkt + "; clip " + error.clip_wkt,
          kExitInternal);
    } catch (const Error& error) {
      out.failure = edit_failure(edit, error.what(), kExitUnreadable);
    }
    if (out.failure) break;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

nlohmann::ordered_json summary(const Landscape& landscape, const Applied& applied) {
  const LandscapeStats stats = landscape.stats();
  nlohmann::ordered_json areas = nlohmann::ordered_json::object();
  for (const auto& [material, twice] : material_areas(landscape)) {
    areas[std::to_string(material)] = to_string(twice);
  }
  nlohmann::ordered_json out;
  out["edits"] = applied.edits;
  out["polygons"] = stats.polygons;
  out["vertices"] = stats.vertices;
  out["cells"] = stats.cells;
  out["depth"] = stats.depth;
  out["area"] = std::move(areas);
  out["state_hash"] = state_hash_hex(landscape.state_hash());
  out["edits_per_second"] =
      applied.seconds > 0 ? static_cast<double>(applied.edits) / applied.seconds : 0.0;
  return out;
}

// --check's last step: every invariant over the whole world (Landscape::check).
std::optional<Failure> final_check(const Landscape& landscape) {
  const LandscapeReport report = landscape.check();
  if (report.ok()) return std::nullopt;
  return Failure{0,
                 "internal error: check() found " + std::to_string(report.problems.size()) +
                     " problem(s), the first: " + one_line(report.problems.front()),
                 kExitInternal};
}

void print_json(nlohmann::ordered_json out, const std::optional<Failure>& failure) {
  if (failure) {
    if (failure->line != 0) out["stopped_at_line"] = failure->line;
    out["error"] = failure->message;
  }
  std::cout << out.dump() << '\n';
}

// --dump and --png; a file that cannot be written is exit 2.
int write_outputs(const Landscape& landscape, const ReplayOptions& options) {
  if (options.dump == "-") {
    std::cout << landscape_dump(landscape) << std::flush;
  } else if (!options.dump.empty()) {
    std::ofstream dump(options.dump, std::ios::binary | std::ios::trunc);
    dump << landscape_dump(landscape);
    if (!dump.flush()) {
      std::cerr << "edgeland replay: cannot write '" << options.dump << "'\n";
      return kExitUnreadable;
    }
  }
  if (!options.png.empty()) {
    try {
      write_landscape_png(landscape, options.png, PngOptions{.cells = options.cells});
    } catch (const PngError& error) {
      std::cerr << "edgeland replay: " << error.what() << '\n';
      return kExitUnreadable;
    }
  }
  return kExitOk;
}

std::string log_name(const ReplayOptions& options) {
  return options.path == "-" ? "standard input" : options.path;
}

int report_failure(const ReplayOptions& options, const Failure& failure) {
  std::cerr << "edgeland replay: " << log_name(options) << ": " << failure.message << '\n';
  return failure.status;
}

}  // namespace

ReplayedWorld replay_world(std::string_view text, bool check) {
  const log::ParsedLandscapeLog parsed = log::parse_landscape_log(text);
  ReplayedWorld out;
  if (!parsed.world) {
    out.failure = Failure{parsed.error->line, parsed.error->what(), kExitUnreadable};
    return out;
  }
  Landscape& landscape = out.world.emplace(log::make_landscape(*parsed.world));
  landscape.set_checked(check);
  const Applied applied = apply_edits(landscape, parsed.edits);
  out.edits = applied.edits;
  out.seconds = applied.seconds;
  out.failure = applied.failure;
  if (!out.failure && parsed.error) {
    out.failure = Failure{parsed.error->line, parsed.error->what(), kExitUnreadable};
  }
  if (check && (!out.failure || out.failure->status != kExitInternal)) {
    if (std::optional<Failure> broken = final_check(landscape)) out.failure = broken;
  }
  return out;
}

int replay_landscape_log(std::string_view text, const ReplayOptions& options) {
  const ReplayedWorld replayed = replay_world(text, options.check);
  if (!replayed.world) {
    print_json({{"edits", 0}}, replayed.failure);
    return report_failure(options, *replayed.failure);
  }
  print_json(summary(*replayed.world, Applied{replayed.edits, replayed.seconds, std::nullopt}),
             replayed.failure);
  const int written = write_outputs(*replayed.world, options);
  if (replayed.failure) return report_failure(options, *replayed.failure);
  return written;
}

}  // namespace edgeland::cli
