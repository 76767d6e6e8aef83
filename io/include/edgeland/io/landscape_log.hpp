#pragma once
// Landscape edit logs: a plain-text record of the edits applied to one Landscape
// (spatial/include/edgeland/spatial/landscape.hpp), so that any world seen in a game can be
// rebuilt and replayed (`edgeland replay`). Landscape::start_log() / log() write exactly this
// format; this is its reader. Both go through one keyword table and one writer of each line,
// edgeland/spatial/log_format.hpp (the landscape records its log, and spatial is below io).
//
// FORMAT (one command per line; README.md "Landscape edit logs"):
//   world X0 Y0 X1 Y1 [MATERIAL]   the world box [X0, X1] x [Y0, Y1], empty or filled with
//                                  MATERIAL; the first command, and only there
//   carve WKT                      everything inside the shape becomes empty space
//   fill MATERIAL WKT              everything inside becomes MATERIAL
//   fill_empty MATERIAL WKT        only the empty space inside becomes MATERIAL
//   replace FROM TO WKT            only material FROM inside becomes TO
//   relabel [FROM TO]... WKT       inside, each FROM becomes its TO, all at once (a FROM at
//                                  most once; materials not named stay)
//   batch EDIT | EDIT | ...        a frame batch (Landscape::apply_batch): one or more of the
//                                  five edits above, each written as its own line would be,
//                                  separated by '|', applied in order as one edit
//   # text                         a comment; blank lines are ignored too
// Materials are decimal integers 0..255 everywhere, 0 being empty space: the library accepts
// every one of them and its recorder writes them back as given, so a recorded log never holds
// a number this reader refuses. So `fill 0` carves, `fill_empty 0` changes nothing,
// `replace 0 M` fills only empty space, `replace M 0` carves only M, and `world ... 0` is an
// empty world. Coordinates are decimal integers with |c| <= kCoordBound, X0 < X1, Y0 < Y1.
// WKT is a POLYGON or MULTIPOLYGON with integer coordinates on the same line, read as in
// continuous-clip logs (clip_log.hpp): a valid edgeland set is taken vertex for vertex (so a
// recorded log replays bit for bit, same state_hash), any other shape with OGC semantics
// (log::shape_to_set, clip_log.hpp). Keywords are lower case and separated by spaces or tabs;
// leading and trailing white space and a final '\r' are ignored.
//
// A log is a landscape log when its first command is `world`; any other first command makes
// it a continuous-clip log (clip_log.hpp). The world line does not record the landscape's
// LandscapeConfig: a log replays onto the default configuration, which is what the state_hash
// of a replay is comparable with.
//
// Part of edgeland::io (io/README.md), with the replay of a whole log in landscape_replay.hpp.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "edgeland/io/wkt_reader.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "edgeland/spatial/log_format.hpp"

namespace edgeland::log {

// `world X0 Y0 X1 Y1 [MATERIAL]`.
struct WorldCommand {
  Box64 box;
  Material fill = kEmpty;
  std::size_t line = 0;  // 1-based line number in the log
};

// LandscapeEditKind and the keywords: log_format.hpp.

// The keyword of an edit as written in a log ("carve", "fill", "fill_empty", "replace",
// "relabel"): log_format.hpp's table.
EDGELAND_EXPORT const char* landscape_edit_keyword(LandscapeEditKind kind) noexcept;

// One edit line.
struct LandscapeEdit {
  LandscapeEditKind kind = LandscapeEditKind::kCarve;
  Material material = kEmpty;  // fill / fill_empty: the material; replace: TO; carve: unused
  Material from = kEmpty;      // replace: FROM; otherwise unused
  MaterialMap map;             // relabel: the pairs; otherwise unused (the identity)
  WktGeometry shape;           // as read
  std::size_t line = 0;        // 1-based line number in the log
  // An edit of a `batch` line: how many edits that line holds (each of them says so, and has
  // the line's number); 0 for an edit line of its own.
  std::size_t batch = 0;
};

// A `batch` line: its edits in order.
struct LandscapeBatch {
  std::vector<LandscapeEdit> edits;
  std::size_t line = 0;
};

using LandscapeCommand = std::variant<WorldCommand, LandscapeEdit, LandscapeBatch>;

enum class LandscapeLogErrorKind : std::uint8_t {
  kUnknownCommand,  // the first word is not one of the seven keywords (in a batch: not one of
                    // the five edits')
  kMissingWorld,    // an edit (or the end of the log) before any world line
  kRepeatedWorld,   // a second world line
  kBadArgument,     // a material or coordinate that is not a decimal integer in its range,
                    // the wrong number of world numbers, an empty world box, or an empty
                    // edit in a batch
  kMissingShape,    // an edit with no WKT after its numbers
  kBadShape,        // the WKT was rejected by the reader (wkt_error holds why)
};

// Stable lower-case name, e.g. "missing-world".
EDGELAND_EXPORT const char* landscape_log_error_kind_name(LandscapeLogErrorKind kind) noexcept;

// A line of a landscape log could not be read. what() is one line starting "line N: ", or
// "line N, column C: " when the place within the line is known (a bad shape: the column of the
// WKT error within the log line, one position for the reader).
class EDGELAND_EXPORT LandscapeLogError : public Error {
 public:
  LandscapeLogError(LandscapeLogErrorKind kind, std::size_t line, const std::string& reason,
                    std::size_t column = 0);
  LandscapeLogErrorKind kind;
  std::size_t line;
  std::size_t column;                     // 1-based within the line; 0: not known
  std::optional<WktErrorKind> wkt_error;  // set for kBadShape
};

// Reads one line (without its '\n'). Nothing for a blank or comment line. Checks the line
// alone (not whether a world line may stand there). Throws LandscapeLogError. O(length).
EDGELAND_EXPORT std::optional<LandscapeCommand> parse_landscape_line(std::string_view line,
                                                                     std::size_t line_number);

// The world and every edit up to the first bad line, and the error of that line if there is
// one. `world` is empty exactly when the log does not start with a good world line (`error`
// then says why: the world line's own error, or kMissingWorld at the first edit, or at line 1
// for a log without commands).
struct ParsedLandscapeLog {
  std::optional<WorldCommand> world;
  std::vector<LandscapeEdit> edits;  // a batch line's edits in a row (LandscapeEdit::batch)
  std::optional<LandscapeLogError> error;
};

// Never throws LandscapeLogError: reading stops at the first bad line. O(length of the text).
EDGELAND_EXPORT ParsedLandscapeLog parse_landscape_log(std::string_view text);

// True when the first command of `text` (skipping blank and comment lines) is `world`: the
// way `edgeland replay` tells the two log kinds apart. O(length up to that command).
EDGELAND_EXPORT bool is_landscape_log(std::string_view text);

// The landscape a world line describes (default configuration and limits). Throws
// InvalidConfig only for a box parse_landscape_line would have refused.
EDGELAND_EXPORT Landscape make_landscape(const WorldCommand& world);

// Applies one edit: the shape is read as log::shape_to_set does (vertex for vertex when it is
// a valid set, else OGC import), then the landscape's edit of that kind runs. Throws what those
// throw: InvalidInput / CoordinateOutOfRange (a shape the kernel refuses), LimitExceeded,
// InternalError (the OGC import failed its checks), LandscapeInternalError. The landscape's
// strong guarantee holds: after a throw it is as it was.
EDGELAND_EXPORT ChangeSet apply_edit(Landscape& landscape, const LandscapeEdit& edit);

// The edit of `kind` with a shape already read: `material` is fill's / fill_empty's material
// and replace's TO, `from` replace's FROM (both unused by carve); a relabel here maps `from`
// to `material` alone (a replace: the whole map needs the LandscapeEdit). Throws as above.
EDGELAND_EXPORT ChangeSet apply_edit(Landscape& landscape, LandscapeEditKind kind,
                                     const PolygonSet& shape, Material material, Material from);

// How many edits, from the first of `edits`, the landscape takes as one step: 1 for an edit
// line, a batch line's count for the first edit of a batch (never more than edits.size()).
EDGELAND_EXPORT std::size_t step_size(std::span<const LandscapeEdit> edits) noexcept;

// Applies one step (`step`: step_size of the edits from one on): an edit line as apply_edit,
// a batch line's edits as one Landscape::apply_batch, every shape read as apply_edit reads it.
// Throws as apply_edit (a shape refused by its edit's error, before anything changed); the
// landscape's strong guarantee holds.
EDGELAND_EXPORT ChangeSet apply_step(Landscape& landscape, std::span<const LandscapeEdit> step);

}  // namespace edgeland::log
