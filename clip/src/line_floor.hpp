#pragma once
// The floor of a segment's line's y at an integer x, exactly: what the grid walks along
// segments (segment_grid.hpp) asks for each column boundary it crosses.
#include <cstdint>

#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"

namespace edgeland::detail {

// floor(a.y + dy * (x - a.x) / dx) for dx > 0 (the line through a with direction (dx, dy)).
inline std::int64_t line_y_floor(Point64 a, Int128 dx, Int128 dy, std::int64_t x) {
  if (dy == 0) return a.y;  // horizontal (tiles, boxes, cell cuts): no division
  const Int128 num = Int128(a.y) * dx + dy * (x - a.x);
  constexpr Int128 kSmall = Int128(1) << 62;
  if (num > -kSmall && num < kSmall) {  // 64-bit division is many times faster
    const std::int64_t n = static_cast<std::int64_t>(num), d = static_cast<std::int64_t>(dx);
    return n / d - (n % d != 0 && n < 0 ? 1 : 0);
  }
  const Int128 q = num / dx;
  return static_cast<std::int64_t>(num % dx != 0 && num < 0 ? q - 1 : q);
}

}  // namespace edgeland::detail
