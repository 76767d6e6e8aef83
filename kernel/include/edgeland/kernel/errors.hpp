#pragma once
// Typed errors: every public operation that rejects its input throws one of these, with the
// offending indices and location as fields, never only inside the message text.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/validate.hpp"

namespace edgeland {

class EDGELAND_EXPORT Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Which operand an InvalidInput error is about: the clipper's subject or clip (a landscape
// edit's shape is its clip), the rings of normalize or import_polygons, or a query's point or
// box.
enum class Operand : std::uint8_t { kSubject, kClip, kRings, kQuery };

// An operand failed validation; `violation` says which rule, polygon and edge.
class EDGELAND_EXPORT InvalidInput : public Error {
 public:
  InvalidInput(Operand operand, Violation violation);
  Operand operand;
  Violation violation;
};

// The one error for a coordinate outside [-kCoordBound, kCoordBound] in an operand: an
// InvalidInput whose violation.rule is Rule::kCoordinateOutOfRange, so it can be caught apart
// (a game clamps a stray tool instead of reporting a broken shape) or with every other
// invalid input. `polygon`, `vertex` and `where` repeat the violation's fields.
class EDGELAND_EXPORT CoordinateOutOfRange : public InvalidInput {
 public:
  CoordinateOutOfRange(Operand operand, Violation violation);
  CoordinateOutOfRange(Operand operand, std::size_t polygon, std::size_t vertex, Point64 where);
  std::size_t polygon;
  std::size_t vertex;
  Point64 where;
};

// Throws CoordinateOutOfRange for a coordinate out of range, InvalidInput for any other rule.
[[noreturn]] EDGELAND_EXPORT void throw_invalid_input(Operand operand, const Violation& violation);

}  // namespace edgeland
