#pragma once
// Pixels of the integer grid, the unit of snap rounding (clip/README.md).
//
// The pixel of integer point c is the half-open square [c.x - 1/2, c.x + 1/2) x
// [c.y - 1/2, c.y + 1/2): exactly the set of points that round_to_grid (predicates.hpp) maps
// to c. Pixels tile the plane. All tests are exact (doubled coordinates, 128-bit products).
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

// Whether the closed segment s has a point in the half-open pixel of c. O(1).
EDGELAND_EXPORT bool segment_meets_pixel(const Segment& s, Point64 c) noexcept;

// Whether the closed segment s meets the CLOSED unit square centred at c (snap rounding's
// "near a hot pixel", which counts the pixel's top and right sides too). Separating axes: x, y
// and the segment's normal (formulas::pixel_line_slack, theorem pixel_line_slack_int128). O(1).
EDGELAND_EXPORT bool segment_meets_closed_pixel(const Segment& s, Point64 c) noexcept;

// (p - s.a) . (s.b - s.a): orders points along the direction of s (exact). O(1).
EDGELAND_EXPORT Int128 projection(const Segment& s, Point64 p) noexcept;

}  // namespace edgeland
