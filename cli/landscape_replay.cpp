#include "landscape_replay.hpp"

#include <fstream>
#include <iostream>
#include <string>

#include "commands.hpp"
#include "landscape_dump.hpp"
#include "landscape_png.hpp"

namespace edgeland::cli {
namespace {

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

int report_failure(const ReplayOptions& options, const log::ReplayFailure& failure) {
  std::cerr << "edgeland replay: " << log_name(options) << ": " << failure.message << '\n';
  return exit_status(failure);
}

}  // namespace

int exit_status(const log::ReplayFailure& failure) {
  return failure.kind == log::ReplayFailure::Kind::kInternal ? kExitInternal : kExitUnreadable;
}

int print_landscape_replay(std::string_view text, const ReplayOptions& options) {
  const log::LandscapeReplay replay =
      log::replay_landscape_log(text, log::LandscapeReplayOptions{.check = options.check});
  std::cout << log::replay_json(replay) << '\n';
  const int written = replay.landscape ? write_outputs(*replay.landscape, options) : kExitOk;
  if (replay.failure) return report_failure(options, *replay.failure);
  return written;
}

}  // namespace edgeland::cli
