#pragma once
// Replaying a landscape edit log (landscape_log.hpp) into a Landscape, and the report
// `edgeland replay` prints for it: one JSON object, the same wherever the library runs (the
// command line, a game, the browser playground through WebAssembly).
//
//   {"edits":N,"polygons":P,"vertices":V,"cells":C,"depth":D,"area":{"0":"A0","1":"A1",...},
//    "state_hash":"H","edits_per_second":S}
//
// area maps each material (decimal, empty space "0" included) whose area is not 0 to twice its
// area, exact, as a decimal string; state_hash is Landscape::state_hash() as 16 hex digits;
// edits_per_second (an integer, for reporting only) is the edits over the time they took. When
// the log could not be applied to the end, "stopped_at_line" and "error" follow: the JSON then
// describes the world after the edits before that line (which are kept). A log whose world line
// is bad has no world to describe: its JSON is {"edits":0,"stopped_at_line":N,"error":"..."}.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::log {

struct LandscapeReplayOptions {
  // Replay in checked mode (Landscape::set_checked) and run Landscape::check() at the end.
  bool check = false;
  // The replayed landscape records its own log from its first edit (Landscape::start_log), so
  // that its log() replays to it bit for bit again: a log loaded to be edited further and shared.
  bool record_log = false;
};

// Why a replay stopped.
struct ReplayFailure {
  enum class Kind : std::uint8_t {
    kUnreadable,  // a bad line, a world line that cannot be read, a shape the kernel refuses
    kInternal,    // a bug in edgeland: LandscapeInternalError, the OGC import's InternalError, or
                  // a failed final check()
  };
  Kind kind = Kind::kUnreadable;
  std::size_t line = 0;  // the log line (1-based); 0 for the final check, about no one line
  std::string message;   // one line, "line N: ..." for a line
};

struct LandscapeReplay {
  std::optional<Landscape> landscape;     // empty only when the log has no good world line
  std::size_t edits = 0;                  // edits applied
  std::chrono::nanoseconds edit_time{0};  // spent applying them
  std::optional<ReplayFailure> failure;
};

// Builds the world of the log's world line and applies its edits in order, up to the first bad
// line or the first edit that throws (the edits before it are kept; an edit that throws changes
// nothing). Never throws for anything in the text; only std::bad_alloc escapes.
EDGELAND_EXPORT LandscapeReplay replay_landscape_log(std::string_view text,
                                                     const LandscapeReplayOptions& options = {});

// The JSON object above, on one line, without a line break.
EDGELAND_EXPORT std::string replay_json(const LandscapeReplay& replay);

// Landscape::state_hash() as 16 lower-case hex digits.
EDGELAND_EXPORT std::string state_hash_hex(std::uint64_t hash);

// Twice the area of every material whose area is not 0, ascending, empty space (0) included:
// the values sum to twice the world's area. O(materials).
EDGELAND_EXPORT std::vector<std::pair<Material, Int128>> material_areas(const Landscape& landscape);

}  // namespace edgeland::log
