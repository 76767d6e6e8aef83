#pragma once
// The shape builders' two steps after rounding (shapes.hpp, "HOW"): the convex hull of the
// rounded corners, and the cut of a convex polygon to the bound's box.
#include <cstdint>
#include <vector>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// Every point the builders compute lies within this bound: a centre within kCoordBound plus an
// offset of at most 2 kMaxShapeRadius + 1 (a rotated box's corner), below 2^35. The formulas
// are proven for it (proofs/: shape_hull_orient_int128, shape_cut_int128).
inline constexpr std::int64_t kShapeCoordBound = std::int64_t{1} << 35;

// The convex hull of the points (Andrew's monotone chain with exact orientation), strictly
// convex and counter-clockwise from the lowest of the leftmost points; fewer than 3 points when
// they all lie on one line. O(n log n).
Polygon convex_hull(std::vector<Point64> points);

// The convex counter-clockwise polygon cut by the four sides of [-kCoordBound, kCoordBound]^2,
// each new corner rounded toward the inside along its side; strictly convex again (a hull), or
// fewer than 3 points when the cut leaves no area.
Polygon cut_to_bound(Polygon convex);

}  // namespace edgeland::detail
