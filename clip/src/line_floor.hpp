#pragma once
// Exact floors for the grid walks along segments (segment_grid.hpp): the floor of a segment's
// line's y at the column boundaries it crosses.
#include <cstdint>

#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"

namespace edgeland::detail {

// floor(num / den) for den > 0.
inline Int128 floor_div(Int128 num, Int128 den) {
  constexpr Int128 kSmall = Int128(1) << 62;
  if (num > -kSmall && num < kSmall && den < kSmall) {  // 64-bit division is many times faster
    const std::int64_t n = static_cast<std::int64_t>(num), d = static_cast<std::int64_t>(den);
    return n / d - (n % d != 0 && n < 0 ? 1 : 0);
  }
  const Int128 q = num / den;
  return num % den != 0 && num < 0 ? q - 1 : q;
}

// floor(a.y + dy * (x - a.x) / dx) at x = x0, x0 + step, x0 + 2 step, ... for dx > 0 (the line
// through a with direction (dx, dy)): one division for the first, then each next one by adding
// the step's quotient and remainder (numerator = q * dx + r with 0 <= r < dx throughout), so a
// walk across many columns costs no division per column.
class LineYFloors {
 public:
  LineYFloors(Point64 a, Int128 dx, Int128 dy, std::int64_t x0, std::int64_t step) : dx_(dx) {
    const Int128 num = Int128(a.y) * dx + dy * (x0 - a.x);
    q_ = floor_div(num, dx);
    r_ = num - q_ * dx;
    const Int128 advance = dy * step;
    step_q_ = floor_div(advance, dx);
    step_r_ = advance - step_q_ * dx;
  }
  // The floor at the current x (in range for every x within the segment's x-span).
  std::int64_t value() const { return static_cast<std::int64_t>(q_); }
  void next() {
    q_ += step_q_;
    r_ += step_r_;
    if (r_ >= dx_) {
      r_ -= dx_;
      ++q_;
    }
  }

 private:
  Int128 dx_, q_ = 0, r_ = 0, step_q_ = 0, step_r_ = 0;
};

}  // namespace edgeland::detail
