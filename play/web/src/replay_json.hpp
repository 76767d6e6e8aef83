#pragma once
// `edgeland replay LOG` for a landscape log, as text: the JSON line the command prints and the
// one-line message it writes to stderr, so that the page's replay answers exactly what the
// native command does for the same log (cli/landscape_replay.cpp over io/.../landscape_replay.hpp).
#include <string>
#include <string_view>

namespace edgeland::play {

struct ReplayOutput {
  std::string json;   // the JSON object, without its newline
  std::string error;  // the stderr line ("" when the log replayed to its end)
  int status = 0;     // the command's exit status (cli/commands.hpp)
};

ReplayOutput replay_landscape_text(std::string_view text);

}  // namespace edgeland::play
