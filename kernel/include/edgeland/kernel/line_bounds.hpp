#pragma once
// Integer bounds on where a segment's line passes: integers lo <= y <= hi around the y it takes
// at an integer x (or the x at an integer y), lo the floor and hi - lo <= 1. clip/'s segment grid
// bounds a segment's offset across a cell with them, so it needs no rational arithmetic of its own.
#include <cstdint>

#include "edgeland/kernel/point.hpp"

namespace edgeland {

struct IntegerRange {
  std::int64_t lo, hi;  // lo <= hi
};

// Bounds lo = floor(y) <= y <= hi <= lo + 1 on the y that the line through a and b takes at x
// (lo == hi at a or b, and on a flat line). Requires a.x != b.x and x between a.x and b.x
// (inclusive), all coordinates within kCoordBound.
IntegerRange line_y_at(Point64 a, Point64 b, std::int64_t x);

// The same with the axes swapped: bounds on the line's x at y (a.y != b.y, y between).
IntegerRange line_x_at(Point64 a, Point64 b, std::int64_t y);

}  // namespace edgeland
