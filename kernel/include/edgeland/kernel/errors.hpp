#pragma once
// Typed errors: every public operation that rejects its input throws one of these, with the
// offending indices and location as fields, never only inside the message text.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/validate.hpp"

namespace edgeland {

class EDGELAND_EXPORT Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Which operand an InvalidInput error is about: the clipper's subject or clip (a landscape
// edit's shape is its clip), the rings of normalize or import_polygons, a query's point or
// box, the polygon (set) of a polygon algorithm (triangulate, convex_pieces, centroid), or the
// points a shape builder is given (shapes.hpp).
enum class Operand : std::uint8_t { kSubject, kClip, kRings, kQuery, kPolygon, kShape };

// An operand failed validation; `violation` says which rule, polygon and edge.
class EDGELAND_EXPORT InvalidInput : public Error {
 public:
  InvalidInput(Operand operand, Violation violation);
  Operand operand;
  Violation violation;

 protected:
  // For subclasses whose message says more than violation.describe() can.
  InvalidInput(Operand operand, Violation violation, const std::string& description);
};

// The one error for a coordinate outside [-kCoordBound, kCoordBound] in an operand: an
// InvalidInput whose violation.rule is Rule::kCoordinateOutOfRange, so it can be caught apart
// (a game clamps a stray tool instead of reporting a broken shape) or with every other
// invalid input. The fields:
//   polygon  the polygon's index in the operand (a set's member; an entry of import_polygons;
//            a ring of normalize; 0 for a query point or a box);
//   ring     the ring's index within that polygon: 0 the exterior, k >= 1 its hole k (only
//            import_polygons' polygons have holes; everywhere else it is 0);
//   vertex   the vertex's index within that ring (kNone for a box's corner);
//   where    the offending point.
// violation.polygon and violation.edge repeat `polygon` and `vertex` (a Violation has no ring).
// The message names the ring when it is not 0: "invalid rings: coordinate-out-of-range:
// polygon 1 ring 2 vertex 0 at (23 2147483648)".
class EDGELAND_EXPORT CoordinateOutOfRange : public InvalidInput {
 public:
  // From validate()'s violation (its polygons are single rings: ring 0).
  CoordinateOutOfRange(Operand operand, Violation violation);
  CoordinateOutOfRange(Operand operand, std::size_t polygon, std::size_t ring, std::size_t vertex,
                       Point64 where);
  // A query's point argument beyond the bound (operand kQuery, polygon 0, ring 0): `vertex` is
  // the argument's index (0: the point, `from` or a box's min; 1: `to` or a box's max), and the
  // message names the argument: "invalid query: coordinate-out-of-range: to at (2147483648 0)".
  static CoordinateOutOfRange query_argument(std::size_t index, const char* name, Point64 where);
  // The same for any operation's point argument: "invalid shape: coordinate-out-of-range:
  // center at (2147483648 0)".
  static CoordinateOutOfRange argument(Operand operand, std::size_t index, const char* name,
                                       Point64 where);
  std::size_t polygon;
  std::size_t ring;
  std::size_t vertex;
  Point64 where;

 private:
  CoordinateOutOfRange(Operand operand, std::size_t vertex, Point64 where,
                       const std::string& description);
};

// A box operand (clip_to_box's box) with min.x > max.x or min.y > max.y while both corners are
// in range (a corner beyond the bound is a CoordinateOutOfRange): an InvalidInput whose
// violation.rule is Rule::kInvertedBox, violation.where = box.min. `box` is the box as given;
// the message names both corners, e.g. "invalid clip: inverted-box: min (5 0) exceeds max
// (0 5) in x".
class EDGELAND_EXPORT InvalidBox : public InvalidInput {
 public:
  InvalidBox(Operand operand, const Box64& box);
  Box64 box;
};

// More vertices than an operation can index or sum exactly: triangulate and convex_pieces
// number vertices in 32 bits, centroid's sums are proven for a bounded vertex count
// (centroid.hpp). `maximum` is the largest count accepted, `requested` the count given.
class EDGELAND_EXPORT TooManyVertices : public Error {
 public:
  TooManyVertices(std::size_t maximum, std::size_t requested);
  std::size_t maximum;
  std::size_t requested;
};

// A numeric argument below the least value an operation accepts (convex_pieces' max_vertices
// below 3). `argument` names it, as in the signature.
class EDGELAND_EXPORT InvalidArgument : public Error {
 public:
  InvalidArgument(const char* argument, std::size_t value, std::size_t minimum);
  const char* argument;
  std::size_t value;
  std::size_t minimum;
};

// A number outside the range an operation accepts (a shape builder's radius, side count, half
// extent or turn denominator: shapes.hpp). `argument` names it as in the signature; the
// accepted range is [minimum, maximum]. "argument out of range: radius = 0, must be in
// [1, 8589934592]".
class EDGELAND_EXPORT ArgumentOutOfRange : public Error {
 public:
  ArgumentOutOfRange(const char* argument, std::int64_t value, std::int64_t minimum,
                     std::int64_t maximum);
  const char* argument;
  std::int64_t value;
  std::int64_t minimum;
  std::int64_t maximum;
};

// A polygon set whose total signed area is not positive, so it has no centroid (centroid.hpp):
// empty, or only rings of zero or negative area. `twice_area` is the total as computed.
class EDGELAND_EXPORT NonPositiveArea : public Error {
 public:
  explicit NonPositiveArea(Int128 twice_area);
  Int128 twice_area;
};

// Throws CoordinateOutOfRange for a coordinate out of range, InvalidInput for any other rule.
[[noreturn]] EDGELAND_EXPORT void throw_invalid_input(Operand operand, const Violation& violation);

}  // namespace edgeland
