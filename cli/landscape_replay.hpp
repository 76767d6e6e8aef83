#pragma once
// `edgeland replay` for a landscape log: the library's replay (edgeland/io/landscape_replay.hpp,
// whose header describes the JSON) printed on one line, then --dump and --png.
#include <string_view>

#include "edgeland/io/landscape_replay.hpp"
#include "replay_options.hpp"

namespace edgeland::cli {

// The exit status (commands.hpp) of a replay that stopped: 2 for a bad line or a shape the kernel
// refuses, 3 for an internal error of the landscape or of the OGC import, or a failed check().
int exit_status(const log::ReplayFailure& failure);

// Returns the exit status (commands.hpp): 0, or exit_status of the failure (a one-line message
// naming the line on stderr).
int print_landscape_replay(std::string_view text, const ReplayOptions& options);

}  // namespace edgeland::cli
