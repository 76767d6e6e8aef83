#pragma once
// Exact comparisons of directions (integer vectors) by angle, for sorting edges around a vertex
// and for the sector tests of the labeling rule. O(1) each.
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland {

// Counter-clockwise order of nonzero directions, starting at angle 0 (the +x axis) inclusive.
// Inline: sorting half-edges around vertices calls it a few times per edge of every operation.
inline bool angle_less(Point64 d1, Point64 d2) noexcept {
  const bool l1 = d1.y < 0 || (d1.y == 0 && d1.x < 0);  // in the lower half-plane
  const bool l2 = d2.y < 0 || (d2.y == 0 && d2.x < 0);
  if (l1 != l2) return l2;
  return orientation({0, 0}, d1, d2) == Orientation::kCounterClockwise;
}

// The same order, computed without branches (both halves evaluated, then selected). For code
// that uses the outcome as data, like ranking the half-edges around a vertex: there which
// direction comes first is a coin toss to the branch predictor. A sort's loop branches on the
// outcome anyway, and there angle_less, which skips the products when the half-planes differ,
// is faster.
inline bool angle_less_branch_free(Point64 d1, Point64 d2) noexcept {
  const bool l1 = (d1.y < 0) | ((d1.y == 0) & (d1.x < 0));
  const bool l2 = (d2.y < 0) | ((d2.y == 0) & (d2.x < 0));
  // d1 x d2, exact for any 64-bit components: each product is below 2^126 in magnitude.
  const bool ccw = Int128(d1.x) * d2.y - Int128(d1.y) * d2.x > 0;
  return l1 != l2 ? l2 : ccw;
}

// Whether direction d lies strictly inside the sector swept counter-clockwise from `from` to
// `to` (from != to as directions; when from and to point the same way the sector is empty).
EDGELAND_EXPORT bool strictly_inside_ccw_sector(Point64 from, Point64 to, Point64 d) noexcept;

}  // namespace edgeland
