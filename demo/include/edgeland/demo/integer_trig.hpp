#pragma once
// Sine and cosine from a table, in integers: angles in 1/256 of a turn, values scaled by
// kTrigOne = 2^14. The demo's shapes need points on circles and waves; a table keeps every
// coordinate an integer that is the same on every platform (no libm, no rounding modes).
#include <array>
#include <cstdint>

#include "edgeland/kernel/point.hpp"

namespace edgeland::demo {

inline constexpr std::int64_t kTrigOne = 16384;  // 2^14: sin of a quarter turn
inline constexpr int kFullTurn = 256;

// round(2^14 sin(2 pi k / 256)) for k = 0..64, the first quarter turn.
inline constexpr std::array<std::int64_t, 65> kQuarterSine{
    0,     402,   804,   1205,  1606,  2006,  2404,  2801,  3196,  3590,  3981,  4370,  4756,
    5139,  5520,  5897,  6270,  6639,  7005,  7366,  7723,  8076,  8423,  8765,  9102,  9434,
    9760,  10080, 10394, 10702, 11003, 11297, 11585, 11866, 12140, 12406, 12665, 12916, 13160,
    13395, 13623, 13842, 14053, 14256, 14449, 14635, 14811, 14978, 15137, 15286, 15426, 15557,
    15679, 15791, 15893, 15986, 16069, 16143, 16207, 16261, 16305, 16340, 16364, 16379, 16384};

// kTrigOne * sin(2 pi angle / 256), any angle (taken modulo a full turn).
constexpr std::int64_t sine(int angle) noexcept {
  const int a = ((angle % kFullTurn) + kFullTurn) % kFullTurn;
  if (a <= 64) return kQuarterSine[static_cast<std::size_t>(a)];
  if (a <= 128) return kQuarterSine[static_cast<std::size_t>(128 - a)];
  if (a <= 192) return -kQuarterSine[static_cast<std::size_t>(a - 128)];
  return -kQuarterSine[static_cast<std::size_t>(256 - a)];
}

constexpr std::int64_t cosine(int angle) noexcept { return sine(angle + kFullTurn / 4); }

// value / kTrigOne rounded to the nearest integer (halves up): arithmetic shift floors.
constexpr std::int64_t unscale(std::int64_t value) noexcept { return (value + kTrigOne / 2) >> 14; }

// The point at distance r (|r| < 2^40) from c in the direction `angle`, on the grid.
constexpr Point64 polar(Point64 c, std::int64_t r, int angle) noexcept {
  return {c.x + unscale(r * cosine(angle)), c.y + unscale(r * sine(angle))};
}

}  // namespace edgeland::demo
