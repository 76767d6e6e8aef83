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

// Whether direction d lies strictly inside the sector swept counter-clockwise from `from` to
// `to` (from != to as directions; when from and to point the same way the sector is empty).
EDGELAND_EXPORT bool strictly_inside_ccw_sector(Point64 from, Point64 to, Point64 d) noexcept;

}  // namespace edgeland
