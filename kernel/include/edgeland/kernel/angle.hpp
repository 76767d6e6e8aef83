#pragma once
// Exact comparisons of directions (integer vectors) by angle, for sorting edges around a vertex
// and for the sector tests of the labeling rule. O(1) each.
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/point.hpp"

namespace edgeland {

// Counter-clockwise order of nonzero directions, starting at angle 0 (the +x axis) inclusive.
EDGELAND_EXPORT bool angle_less(Point64 d1, Point64 d2) noexcept;

// Whether direction d lies strictly inside the sector swept counter-clockwise from `from` to
// `to` (from != to as directions; when from and to point the same way the sector is empty).
EDGELAND_EXPORT bool strictly_inside_ccw_sector(Point64 from, Point64 to, Point64 d) noexcept;

}  // namespace edgeland
