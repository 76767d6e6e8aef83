#pragma once
// Integer bounds on where a segment's line passes: the floor and the ceiling of the y it takes
// at an integer x (or of the x at an integer y). clip/'s segment grid bounds a segment's offset
// across a cell with them, so it needs no rational arithmetic of its own.
#include <cstdint>

#include "edgeland/kernel/point.hpp"

namespace edgeland {

struct IntegerRange {
  std::int64_t lo, hi;  // lo <= hi; equal when the value is an integer
};

// floor and ceil of the y that the line through a and b takes at x. Requires a.x != b.x and
// x between a.x and b.x (inclusive), all coordinates within kCoordBound.
IntegerRange line_y_at(Point64 a, Point64 b, std::int64_t x);

// The same with the axes swapped: floor and ceil of the line's x at y (a.y != b.y, y between).
IntegerRange line_x_at(Point64 a, Point64 b, std::int64_t y);

}  // namespace edgeland
