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
// violation found by the sweep but stops after `max_violations`.
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
