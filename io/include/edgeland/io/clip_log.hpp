#pragma once
// Continuous-clip logs: a plain-text record of the operations applied to one evolving polygon
// set, so that any sequence of clips seen in the field can be replayed (`edgeland replay`).
//
// FORMAT (one step per line; README.md "Continuous-clip logs"):
//   set WKT           the current set becomes the WKT's region
//   union WKT         current := current OP shape, for the four boolean operations
//   intersection WKT
//   difference WKT
//   xor WKT
//   # text            a comment; blank lines are ignored too
// WKT is a POLYGON or MULTIPOLYGON with integer coordinates (wkt_reader.hpp), on the same
// line. Keywords are lower case and separated from the WKT by spaces or tabs; leading and
// trailing white space and a final '\r' are ignored.
//
// A WKT that already is a valid edgeland polygon set (hole-free members that pass
// kernel/validate.hpp as a set) is taken vertex for vertex, so that a recorded state replays
// bit for bit; any other WKT is imported with OGC semantics (clip.hpp import_polygons:
// exteriors minus holes, members united). Both readings describe the same region.
//
// Part of edgeland::io (io/README.md).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "edgeland/clip/clip.hpp"
#include "edgeland/io/wkt_reader.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::log {

enum class StepKind : std::uint8_t { kSet, kUnion, kIntersection, kDifference, kXor };

// The keyword of a step as written in a log ("set", "union", ...).
EDGELAND_EXPORT const char* step_keyword(StepKind kind) noexcept;
// The step that applies `op` to the current set.
EDGELAND_EXPORT StepKind step_kind(ClipOp op) noexcept;

// One parsed line.
struct Step {
  StepKind kind = StepKind::kSet;
  WktGeometry shape;     // the operand as read
  std::size_t line = 0;  // 1-based line number in the log
};

enum class LogErrorKind : std::uint8_t {
  kUnknownStep,   // the first word is not one of the five keywords
  kMissingShape,  // a keyword with no WKT after it
  kBadShape,      // the WKT was rejected by the reader (wkt_error holds why)
};

// Stable lower-case name, e.g. "unknown-step".
EDGELAND_EXPORT const char* log_error_kind_name(LogErrorKind kind) noexcept;

// A line of a log could not be read. what() is one line starting "line N: ", or
// "line N, column C: " when the place within the line is known (as for LandscapeLogError).
class EDGELAND_EXPORT LogError : public Error {
 public:
  LogError(LogErrorKind kind, std::size_t line, const std::string& reason, std::size_t column = 0);
  LogErrorKind kind;
  std::size_t line;
  std::size_t column;                     // 1-based within the line; 0: not known
  std::optional<WktErrorKind> wkt_error;  // set for kBadShape
};

// Reads one line (without its '\n'). Returns nothing for a blank or comment line.
// Throws LogError. O(length of the line).
EDGELAND_EXPORT std::optional<Step> parse_log_line(std::string_view line, std::size_t line_number);

// Every step of a log up to the first bad line, and the error of that line if there is one.
struct ParsedLog {
  std::vector<Step> steps;
  std::optional<LogError> error;
};

// Never throws LogError: reading stops at the first bad line. O(length of the text).
EDGELAND_EXPORT ParsedLog parse_log(std::string_view text);

// The operand a shape stands for (see the note on valid sets above). Throws InvalidInput /
// InternalError from import_polygons only.
EDGELAND_EXPORT PolygonSet shape_to_set(const WktGeometry& shape, const ClipOptions& options = {});

// One polygon set changed in place by a sequence of steps. Kept as a ValidSet: the set is
// validated when it is assigned, not again on every step (a long log costs each step's change,
// not a validation of the whole set).
class EDGELAND_EXPORT EvolvingSet {
 public:
  EvolvingSet() = default;
  // Throws InvalidInput if `initial` is not a valid set.
  explicit EvolvingSet(PolygonSet initial) : current_(std::move(initial)) {}

  // Applies one step. Strong guarantee: if it throws (InvalidInput, InternalError, ...) the
  // set is left exactly as it was.
  void apply(const Step& step, const ClipOptions& options = {});
  // current := current OP operand (operand must be valid, else InvalidInput).
  ClipStats apply(ClipOp op, const PolygonSet& operand, const ClipOptions& options = {});
  // Throws InvalidInput (and keeps the set) if `set` is not valid.
  void assign(PolygonSet set) { current_ = ValidSet(std::move(set)); }

  const PolygonSet& current() const noexcept { return current_.polygons(); }

 private:
  ValidSet current_;
};

// Records operations as log text. Typical use in a game: keep one EditLog per evolving set,
// call record_clip after (or instead of, via clip()) each operation, and save text() when a
// failure is reported.
class EDGELAND_EXPORT EditLog {
 public:
  // A `# text` line (line breaks in `text` become spaces).
  void comment(std::string_view text);
  // A `set` line: the current set becomes `set`.
  void record_set(const PolygonSet& set);
  // Records `subject OP operand`. When `subject` is not the set the log currently ends with
  // (the last recorded set or result), a `set subject` line is written first, so any
  // sequence of clips on any sets is recorded faithfully. `result` is what the operation gave
  // (the state the next step starts from).
  void record_clip(ClipOp op, const PolygonSet& subject, const PolygonSet& operand,
                   const PolygonSet& result);
  // Runs clip() and records it (nothing is recorded when clip throws InvalidInput; an
  // InternalError is recorded with a comment so the log ends with the failing step).
  ClipResult clip(ClipOp op, const PolygonSet& subject, const PolygonSet& operand,
                  const ClipOptions& options = {});

  const std::string& text() const noexcept { return text_; }
  std::size_t steps() const noexcept { return steps_; }

 private:
  void write_step(StepKind kind, const PolygonSet& shape);
  std::string text_;
  std::size_t steps_ = 0;
  std::optional<PolygonSet> state_;  // the set the log ends with, if known
};

// FNV-1a 64-bit hash of `text`, as 16 lower-case hex digits. Deterministic on every platform.
EDGELAND_EXPORT std::string fnv1a64_hex(std::string_view text);

// The state hash `edgeland replay` prints: fnv1a64_hex(to_wkt(set)), i.e. the hash of the
// WKT that `--dump` writes (without its final newline).
EDGELAND_EXPORT std::string state_hash(const PolygonSet& set);

}  // namespace edgeland::log
