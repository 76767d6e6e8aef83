#pragma once
// Convexity of a ring (thesis 2.3).
#include <cstdint>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

// What a caller knows about a ring's shape; lets the intersection and ray queries stop
// early on convex rings (thesis 2.4.1, 2.4.2). Passing kConvex for a ring that is not
// convex (see is_convex) breaks the query's contract.
enum class RingShape : std::uint8_t { kGeneral, kConvex };

// True when the ring bounds a convex region of positive area, in either orientation.
//
// Collinear vertices ARE allowed: a vertex whose two edges continue in the same direction
// (an interior angle of exactly 180 degrees) keeps the ring convex, following the thesis's
// "less or equal 180 degrees". Rejected: fewer than 3 vertices, a repeated consecutive
// vertex (zero-length edge), a fold-back (two consecutive edges in opposite directions),
// turns of both signs, and rings whose turns all agree but that wind around more than once
// (a pentagram), which the thesis's local test of figure 7 alone would accept.
//
// Exact; O(n): one orientation test and one sign comparison per vertex.
EDGELAND_EXPORT bool is_convex(const Ring& ring) noexcept;

}  // namespace edgeland
