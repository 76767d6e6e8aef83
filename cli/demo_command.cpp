// `edgeland demo [--out DIR] [--edits N] [--seed S] [--cells] [--save FILE] [--log FILE]
// [--unchecked]`: the landscape demo. Builds a deterministic 8192 x 8192 world and lets N edits
// of explosions, tunnels, floods, veins and landslides loose on it (demo/: edgeland/demo/
// landscape.hpp) in checked mode, runs Landscape::check(), prints a summary as readable
// lines and draws DIR/landscape.png. --save writes the landscape's save file, --log its recorded
// edit log (which `edgeland replay` turns back into the same state hash).
// `edgeland demo --physics [--out DIR] [--frames N] [--frame-every K] [--seed S]`: the physics
// demo instead (physics_demo.hpp), when built with Box2D.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "edgeland/demo/landscape.hpp"
#include "edgeland/io/landscape_replay.hpp"
#include "landscape_png.hpp"
#ifdef EDGELAND_HAVE_BOX2D
#include "physics_demo.hpp"
#endif

namespace edgeland::cli {
namespace {

struct DemoOptions {
  std::string out = ".";
  std::size_t edits = 6000;
  std::uint64_t seed = 1;
  bool cells = false;
  bool unchecked = false;
  std::string save;
  std::string log;
  bool physics = false;
  int frames = 600, frame_every = 30;
};

struct DemoRun {
  demo::DemoBuild build;
  double seconds = 0;
};

DemoRun run_edits(Landscape& landscape, const DemoOptions& options) {
  DemoRun run;
  const auto start = std::chrono::steady_clock::now();
  run.build = demo::build_demo(landscape, options.seed, options.edits);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

void print_line(const std::string& label, const std::string& value) {
  std::cout << std::left << std::setw(18) << (label + ":") << value << '\n';
}

void print_summary(const Landscape& landscape, const DemoRun& run, const LandscapeReport& report) {
  const demo::ActionCounts& a = run.build.actions;
  const std::size_t action_edits =
      a.explosions + a.tunnel_steps + a.floods + a.vein_steps + a.landslides + a.drifts;
  const std::size_t edits = run.build.world_edits + action_edits;
  const LandscapeStats stats = landscape.stats();
  std::ostringstream rate;
  rate << std::fixed << std::setprecision(0)
       << (run.seconds > 0 ? static_cast<double>(edits) / run.seconds : 0.0) << " ("
       << std::setprecision(2) << run.seconds << " s)";
  print_line("world built", std::to_string(run.build.world_edits) +
                                " edits (layers, grass, ore and sand bands, caves, pools)");
  print_line("actions", std::to_string(action_edits) + " edits: " + std::to_string(a.explosions) +
                            " explosions, " + std::to_string(a.tunnel_steps) + " tunnel steps, " +
                            std::to_string(a.floods) + " floods, " + std::to_string(a.vein_steps) +
                            " vein steps, " + std::to_string(a.landslides) + " landslides, " +
                            std::to_string(a.drifts) + " sand drifts");
  print_line("edits", std::to_string(edits));
  print_line("edits per second", rate.str());
  print_line("polygons", std::to_string(stats.polygons));
  print_line("vertices", std::to_string(stats.vertices));
  print_line("cells", std::to_string(stats.cells));
  print_line("depth", std::to_string(stats.depth));
  print_line("memory bytes", std::to_string(stats.bytes));
  print_line("state hash", log::state_hash_hex(landscape.state_hash()));
  print_line("check()", report.ok() ? "ok"
                                    : std::to_string(report.problems.size()) +
                                          " problem(s): " + report.problems.front());
}

// A file the demo was asked to write; false (with a message) when it cannot be written.
bool write_file(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
  if (out.flush()) return true;
  std::cerr << "edgeland demo: cannot write '" << path << "'\n";
  return false;
}

// An internal error keeps its evidence: the state before the failing edit and a log that
// replays to it, beside the picture.
int report_internal_error(const LandscapeInternalError& error, const std::filesystem::path& out) {
  const std::string state = (out / "demo_failure.state").string();
  const std::string log = (out / "demo_failure.log").string();
  write_file(state, error.state);
  write_file(log, error.log);
  std::string what = error.what();
  for (char& c : what) c = c == '\n' ? ' ' : c;
  std::cerr << "edgeland demo: " << what << " (state: " << state << ", log: " << log << ")\n";
  return kExitInternal;
}

int write_outputs(const Landscape& landscape, const DemoOptions& options) {
  const std::string png = (std::filesystem::path(options.out) / "landscape.png").string();
  try {
    write_landscape_png(landscape, png, PngOptions{.cells = options.cells});
  } catch (const PngError& error) {
    std::cerr << "edgeland demo: " << error.what() << '\n';
    return kExitUnreadable;
  }
  print_line("picture", png);
  if (!options.save.empty()) {
    std::ostringstream bytes;
    landscape.save(bytes);
    if (!write_file(options.save, bytes.str())) return kExitUnreadable;
    print_line("save file", options.save);
  }
  if (!options.log.empty()) {
    if (!write_file(options.log, landscape.log())) return kExitUnreadable;
    print_line("edit log", options.log);
  }
  return kExitOk;
}

// The output folder made (with its parents) for either demo; false, said on stderr, if it cannot
// be.
bool output_folder_made(const std::string& out) {
  std::error_code error;
  std::filesystem::create_directories(out, error);
  if (error)
    std::cerr << "edgeland demo: cannot create '" << out << "': " << error.message() << '\n';
  return !error;
}

int run_demo(const DemoOptions& options) {
  if (options.physics) {
#ifdef EDGELAND_HAVE_BOX2D
    if (!output_folder_made(options.out)) return kExitUnreadable;
    return run_physics_demo({options.out, options.frames, options.frame_every, options.seed});
#else
    std::cerr << "edgeland demo: --physics needs Box2D: this edgeland was built without it "
                 "(apt-get install -y libbox2d-dev)\n";
    return kExitUnreadable;
#endif
  }
  if (!output_folder_made(options.out)) return kExitUnreadable;
  Landscape landscape(demo::kDemoWorld);
  landscape.set_checked(!options.unchecked);
  if (!options.log.empty()) landscape.start_log();
  std::cout << "edgeland demo: world 0 0 8192 8192, seed " << options.seed << ", checked mode "
            << (options.unchecked ? "off" : "on") << '\n';
  DemoRun run;
  try {
    run = run_edits(landscape, options);
  } catch (const LandscapeInternalError& failure) {
    return report_internal_error(failure, options.out);
  }
  const LandscapeReport report = landscape.check();
  print_summary(landscape, run, report);
  const int written = write_outputs(landscape, options);
  return report.ok() ? written : kExitInternal;
}

}  // namespace

Command add_demo_command(CLI::App& parent) {
  auto options = std::make_shared<DemoOptions>();
  CLI::App* app = parent.add_subcommand(
      "demo",
      "The landscape demo: a layered 8192 x 8192 world of bedrock, rock, dirt, ore and water, "
      "then explosions, tunnels, floods and ore veins in checked mode; prints a summary and "
      "draws DIR/landscape.png.");
  app->add_option("--out", options->out, "Directory for landscape.png (created if missing)")
      ->capture_default_str();
  app->add_option("--edits", options->edits, "Edits after the world is built")
      ->capture_default_str();
  app->add_option("--seed", options->seed, "Seed of the random world and edits")
      ->capture_default_str();
  app->add_flag("--cells", options->cells, "Draw the cell lines in the picture");
  app->add_option("--save", options->save, "Also write the landscape's save file here");
  app->add_option("--log", options->log,
                  "Also record the edit log and write it here (`edgeland replay` reads it)");
  app->add_flag("--unchecked", options->unchecked, "Edit without checked mode (faster)");
  app->add_flag("--physics", options->physics,
                "The physics demo instead: 200 balls and boxes on a 4096 x 4096 world under "
                "blasts and fills, debris falling (Box2D); PNG frames DIR/physics_NNNN.png");
  app->add_option("--frames", options->frames, "--physics: frames after the bodies land")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app->add_option("--frame-every", options->frame_every, "--physics: draw every K-th frame")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app->footer(
      "Deterministic: the same seed and edit count give the same state hash. Exit status: 0; 2 "
      "when an output cannot be written; 3 when an edit hits an internal error (its state and "
      "log are written to DIR/demo_failure.state and .log) or check() fails.");
  return {app, [options] { return run_demo(*options); }};
}

}  // namespace edgeland::cli
