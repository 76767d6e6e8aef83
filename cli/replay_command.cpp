// `edgeland replay LOG [--check] [--dump FILE] [--png FILE.png] [--cells]`: replays a log and
// prints one JSON object on one line. The first command tells the two log kinds apart: `world`
// starts a landscape log (edgeland/io/landscape_log.hpp, replayed by
// edgeland/io/landscape_replay.hpp, whose header describes its JSON); anything else is a
// continuous-clip log (edgeland/io/clip_log.hpp), applied here to an initially empty set:
//   {"steps":N,"polygons":P,"vertices":V,"twice_area":"A","state_hash":"H","steps_per_second":S}
// plus, when the log could not be applied to the end, "stopped_at_line" and "error": the JSON
// then describes the state after the steps before that line (which are kept).
// twice_area is the exact integer 2 * area as a decimal string; state_hash is
// edgeland::log::state_hash (FNV-1a 64 of the state's WKT, i.e. of the --dump text without its
// final newline); steps_per_second is for reporting only.
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "commands.hpp"
#include "edgeland/demo/input_text.hpp"
#include "edgeland/io/clip_log.hpp"
#include "edgeland/io/landscape_log.hpp"
#include "edgeland/io/log_kind.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "landscape_replay.hpp"
#include "replay_options.hpp"

namespace edgeland::cli {
namespace {

struct Failure {
  std::size_t line = 0;
  std::string message;
  int status = kExitOk;
};

nlohmann::ordered_json summary(const PolygonSet& set, std::size_t steps, double seconds) {
  std::size_t vertices = 0;
  for (const Polygon& polygon : set) vertices += polygon.size();
  nlohmann::ordered_json out;
  out["steps"] = steps;
  out["polygons"] = set.size();
  out["vertices"] = vertices;
  out["twice_area"] = to_string(twice_signed_area(set));
  out["state_hash"] = log::state_hash(set);
  out["steps_per_second"] = seconds > 0 ? static_cast<double>(steps) / seconds : 0.0;
  return out;
}

int replay_clip_log(std::string_view text, const ReplayOptions& options) {
  const log::ParsedLog parsed = log::parse_log(text);
  const std::string name = options.path == "-" ? "standard input" : options.path;

  log::EvolvingSet state;
  std::size_t applied = 0;
  Failure failure;
  const auto start = std::chrono::steady_clock::now();
  for (const log::Step& step : parsed.steps) {
    try {
      state.apply(step, ClipOptions{.checked = options.check});
      ++applied;
    } catch (const InternalError& error) {
      // A bug in edgeland: the message names the operation; the inputs are printed as WKT.
      failure = {step.line,
                 "line " + std::to_string(step.line) + ": internal error: " + error.what() +
                     "; subject " + error.subject_wkt + "; clip " + error.clip_wkt,
                 kExitInternal};
      break;
    } catch (const Error& error) {
      failure = {step.line, "line " + std::to_string(step.line) + ": " + error.what(),
                 kExitUnreadable};
      break;
    }
  }
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  if (failure.status == kExitOk && parsed.error) {
    failure = {parsed.error->line, parsed.error->what(), kExitUnreadable};
  }

  nlohmann::ordered_json out = summary(state.current(), applied, elapsed.count());
  if (failure.status != kExitOk) {
    out["stopped_at_line"] = failure.line;
    out["error"] = failure.message;
  }
  std::cout << out.dump() << '\n';

  if (options.dump == "-") {
    std::cout << to_wkt(state.current()) << '\n' << std::flush;
  } else if (!options.dump.empty()) {
    std::ofstream dump(options.dump, std::ios::binary | std::ios::trunc);
    dump << to_wkt(state.current()) << '\n';
    if (!dump.flush()) {
      std::cerr << "edgeland replay: cannot write '" << options.dump << "'\n";
      return kExitUnreadable;
    }
  }
  if (failure.status != kExitOk) {
    std::cerr << "edgeland replay: " << name << ": " << failure.message << '\n';
  }
  return failure.status;
}

int run_replay(const ReplayOptions& options) {
  std::string text;
  try {
    text = demo::read_input_text(options.path);
  } catch (const demo::InputError& error) {
    std::cerr << "edgeland replay: " << error.what() << '\n';
    return kExitUnreadable;
  }
  const log::LogStart start = log::log_start(text);
  if (const std::optional<std::string> problem = log::log_start_problem(start)) {
    std::cerr << "edgeland replay: " << (options.path == "-" ? "standard input" : options.path)
              << ": " << *problem << '\n';
    return kExitUnreadable;
  }
  if (start.kind == log::LogKind::kLandscape) return print_landscape_replay(text, options);
  if (!options.png.empty() || options.cells) {
    std::cerr << "edgeland replay: --png and --cells need a landscape log (one whose first "
                 "command is `world`)\n";
    return kExitUnreadable;
  }
  return replay_clip_log(text, options);
}

}  // namespace

Command add_replay_command(CLI::App& parent) {
  auto options = std::make_shared<ReplayOptions>();
  CLI::App* app = parent.add_subcommand(
      "replay",
      "Replay an edit log and print the final state as one JSON line: a landscape log "
      "(first command `world`, then carve/fill/fill_empty/replace/relabel WKT) or a "
      "continuous-clip "
      "log (set/union/intersection/difference/xor WKT, one step per line).");
  app->add_option("LOG", options->path, "log file, or - for standard input")->required();
  app->add_flag("--check", options->check,
                "Checked mode: validate every step's output (landscape: Landscape::set_checked, "
                "and check() at the end)");
  app->add_option("--dump", options->dump,
                  "Write the final state to this file (- = standard output, after the JSON): "
                  "one WKT line; for a landscape, one `MATERIAL<TAB>MULTIPOLYGON` line per "
                  "material");
  app->add_option("--png", options->png, "Landscape logs: draw the final world into this PNG");
  app->add_flag("--cells", options->cells, "Landscape logs: draw the cell lines in the PNG");
  app->footer(
      "Prints {steps, polygons, vertices, twice_area, state_hash, steps_per_second} for a "
      "continuous-clip log, {edits, polygons, vertices, cells, depth, area, state_hash, "
      "edits_per_second} for a landscape log, as JSON. "
      "Exit status: 0 when every step was applied; 2 for a file with no command or whose first "
      "command starts neither kind of log (one line on stderr, no JSON), and at the first bad "
      "line or shape (the JSON then describes the steps before it and adds stopped_at_line and "
      "error; --dump and --png are still written, of that same state; a one-line message "
      "naming the line goes to stderr); 3 when a step hits an internal error (or, with "
      "--check, the landscape's final check fails).");
  return {app, [options] { return run_replay(*options); }};
}

}  // namespace edgeland::cli
