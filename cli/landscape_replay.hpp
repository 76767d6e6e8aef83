#pragma once
// `edgeland replay` for a landscape log: the library's replay (edgeland/io/landscape_replay.hpp,
// whose header describes the JSON) printed on one line, then --dump and --png.
#include <string_view>

#include "replay_options.hpp"

namespace edgeland::cli {

// Returns the exit status (command.hpp): 0; 2 for a bad line or a shape the kernel refuses (a
// one-line message naming the line on stderr); 3 for an internal error of the landscape or of
// the OGC import, or a failed final check() with --check.
int replay_landscape_log(std::string_view text, const ReplayOptions& options);

}  // namespace edgeland::cli
