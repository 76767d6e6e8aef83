#pragma once
// Invariant checkers (public): tests, fuzzers, the CLI and the clipper's checked mode all
// call these same functions.
//
// A valid polygon: >= 3 vertices, every coordinate in range, no repeated consecutive vertex,
// strictly simple (non-adjacent edges share no point; adjacent edges share only their common
// vertex, so no collinear fold-back or spike), counter-clockwise with positive area.
// A valid polygon set: every member valid, interiors pairwise disjoint (boundaries may touch
// along edges or at vertices).
//
// Complexity: O(n log n) in the total vertex count (sweep line); the report lists every
// violation found by the sweep but stops after `max_violations`. A valid input of smooth rings
// that do not touch each other costs O(n) plus a sort of about n / 32 monotone runs (the
// clipper validates every operand, so this is its common case).
//
// What is checked, in order (the report follows polygon order, then overlaps):
//   1. each ring on its own: too few vertices (nothing else is checked then); every vertex out
//      of range and every zero-length edge (a ring with either gets no geometric check, so
//      no arithmetic ever sees an out-of-range coordinate); every spike; the first
//      self-intersection the sweep meets (one per ring); and, only for a ring that is
//      strictly simple, its orientation;
//   2. the rings that passed step 1, together: one sweep finds one overlapping pair, reports
//      it, drops the later member of the pair and sweeps again, so k reported overlaps cost
//      k + 1 sweeps (k <= max_violations).
// An invalid input always yields at least one violation, even with max_violations == 0.
// The input needs no precondition: any vector of int64 points is accepted.
//
// Violation fields per rule (`edge` i is the edge from vertex i to vertex i + 1):
//   too-few-vertices        polygon; where = vertex 0 (or (0 0) for an empty ring)
//   coordinate-out-of-range polygon, edge = the offending vertex; where = that vertex
//   repeated-vertex         polygon, edge = the zero-length edge; where = its vertex
//   spike                   polygon, edge and other_edge = the two edges folding back at
//                           their common vertex `where`
//   self-intersection       polygon, edge < other_edge, non-adjacent; where = a common point
//                           (a crossing point is rounded by round_to_grid)
//   not-counter-clockwise   polygon; where = its lexicographically smallest vertex
//   overlapping-interiors   polygon < other_polygon with an edge of each near `where`, a point
//                           on the boundary of the common part (or a rounded crossing point)
//   inverted-box            never reported by validate(): clip_to_box's box with min > max
//                           (the InvalidBox error of errors.hpp holds the whole box);
//                           where = box.min
#include <cstddef>
#include <string>
#include <vector>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

enum class Rule : std::uint8_t {
  kTooFewVertices,        // fewer than 3 vertices
  kCoordinateOutOfRange,  // |c| > kCoordBound
  kRepeatedVertex,        // vertex i equals vertex i + 1
  kSelfIntersection,      // two edges of one ring share a point they must not
  kSpike,                 // adjacent edges fold back on each other (collinear overlap)
  kNotCounterClockwise,   // signed area <= 0
  kOverlappingInteriors,  // two members of a set share interior points
  kInvertedBox,           // a box operand with min.x > max.x or min.y > max.y (errors.hpp)
};

// Stable lower-case name of a rule, e.g. "self-intersection".
EDGELAND_EXPORT const char* rule_name(Rule rule) noexcept;

inline constexpr std::size_t kNone = static_cast<std::size_t>(-1);

struct Violation {
  Rule rule = Rule::kTooFewVertices;
  std::size_t polygon = 0;            // index in the set (0 for a single polygon)
  std::size_t edge = kNone;           // edge i runs from vertex i to vertex i + 1
  std::size_t other_polygon = kNone;  // second polygon involved, if any
  std::size_t other_edge = kNone;     // second edge involved, if any
  Point64 where;                      // a point where the violation is seen
  // One line, e.g. "self-intersection: polygon 0 edges 0 and 2 at (5 5)".
  EDGELAND_EXPORT std::string describe() const;
};

struct ValidationReport {
  std::vector<Violation> violations;
  bool ok() const noexcept { return violations.empty(); }
};

inline constexpr std::size_t kDefaultMaxViolations = 64;

EDGELAND_EXPORT ValidationReport validate(const Polygon& polygon,
                                          std::size_t max_violations = kDefaultMaxViolations);
EDGELAND_EXPORT ValidationReport validate(const PolygonSet& set,
                                          std::size_t max_violations = kDefaultMaxViolations);

}  // namespace edgeland
