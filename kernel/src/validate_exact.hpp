#pragma once
// Private to validate_*.cpp: the exact signs the sweeps ask for, in the cheapest exact form.
//
// Coordinates are in range (|c| <= 2^31 - 1, point.hpp), so every difference of two of them
// fits 33 bits: it is formed in int64 (checked in the checked build). Any product of two int64
// values fits Int128 (|a * b| < 2^126), and so does the difference of two such products, so one
// widening multiply per product is exact: no 128 x 128 multiply, no overflow to prove beyond
// the differences (proofs/ bounds the same orient and cross formulas at 66 bits).
#include <cstdint>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"

namespace edgeland::detail {

inline std::int64_t coord_diff(std::int64_t a, std::int64_t b) noexcept {
  return arith::sub<std::int64_t>(a, b);
}

// Sign of the cross product (ux, uy) x (vx, vy) of two coordinate differences.
inline int cross_sign(std::int64_t ux, std::int64_t uy, std::int64_t vx, std::int64_t vy) noexcept {
  const Int128 l = Int128(ux) * vy, r = Int128(uy) * vx;
  return (l > r) - (l < r);
}

// Sign of orient(a, b, c): +1 when c is left of a->b, 0 when collinear.
inline int orient_sign(Point64 a, Point64 b, Point64 c) noexcept {
  return cross_sign(coord_diff(b.x, a.x), coord_diff(b.y, a.y), coord_diff(c.x, a.x),
                    coord_diff(c.y, a.y));
}

}  // namespace edgeland::detail
