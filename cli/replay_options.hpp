#pragma once
// The options of `edgeland replay`, shared by its two log kinds (replay_command.cpp for
// continuous-clip logs, landscape_replay.cpp for landscape logs).
#include <string>

namespace edgeland::cli {

struct ReplayOptions {
  std::string path;    // the log, "-" = standard input
  bool check = false;  // checked mode while replaying, and a final check for landscapes
  std::string dump;    // write the final state here ("" = no dump, "-" = standard output)
  std::string png;     // landscape logs: write a picture here
  bool cells = false;  // landscape logs: draw the cell lines in the picture
};

}  // namespace edgeland::cli
