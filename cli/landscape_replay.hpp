#pragma once
// `edgeland replay` for a landscape log (landscape_log.hpp): builds the world, applies the edits
// and prints one JSON object on one line:
//   {"edits":N,"polygons":P,"vertices":V,"cells":C,"depth":D,"area":{"0":"A0","1":"A1",...},
//    "state_hash":"H","edits_per_second":S}
// area maps each material (decimal, empty space "0" included) whose area is not 0 to twice its
// area, exact, as a decimal string; state_hash is Landscape::state_hash() as 16 hex digits;
// edits_per_second is for reporting only. When the log could not be applied to the end,
// "stopped_at_line" and "error" follow: the JSON then describes the world after the edits
// before that line (which are kept). A log whose world line is bad has no world to describe:
// its JSON is {"edits":0,"stopped_at_line":N,"error":"..."}.
#include <optional>
#include <string>
#include <string_view>

#include "edgeland/spatial/landscape.hpp"
#include "replay_options.hpp"

namespace edgeland::cli {

// Why a replay stopped: a line (0: not about one line, the final check), a one-line message
// naming it, and the exit status (command.hpp).
struct ReplayFailure {
  std::size_t line = 0;
  std::string message;
  int status = 0;
};

// A landscape log applied: the world after every edit before the first failure.
struct ReplayedWorld {
  std::optional<Landscape> world;  // empty when the log has no good world line
  std::size_t edits = 0;           // edits applied
  double seconds = 0;              // their time (reporting only)
  std::optional<ReplayFailure> failure;
};

// Parses and applies a landscape log (checked mode with `check`, and then check() at the end).
ReplayedWorld replay_world(std::string_view text, bool check);

// Returns the exit status (command.hpp): 0; 2 for a bad line or a shape the kernel refuses (a
// one-line message naming the line on stderr); 3 for an internal error of the landscape or of
// the OGC import, or a failed final check() with --check.
int replay_landscape_log(std::string_view text, const ReplayOptions& options);

}  // namespace edgeland::cli
