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

// A box no wider and no taller than this is narrow: any difference of two coordinates in it
// is at most 2^31 - 1 in magnitude, so a product of two differences is at most
// (2^31 - 1)^2 < 2^62 and a difference of two products below 2^63. Cross products of
// differences within a narrow box are exact in int64: one plain multiply per product,
// one subtraction and a sign, no 128-bit compare. (Input in range spans up to 2^32 - 2.)
inline constexpr std::int64_t kNarrowSide = (std::int64_t{1} << 31) - 1;

inline bool narrow_box(Point64 low, Point64 high) noexcept {
  return coord_diff(high.x, low.x) <= kNarrowSide && coord_diff(high.y, low.y) <= kNarrowSide;
}

// cross_sign for coordinate differences within one narrow box (checked in the checked build).
inline int cross_sign_narrow(std::int64_t ux, std::int64_t uy, std::int64_t vx,
                             std::int64_t vy) noexcept {
  const std::int64_t d = arith::sub(arith::mul(ux, vy), arith::mul(uy, vx));
  return (d > 0) - (d < 0);
}

// cross_sign in the width a sweep chose: kNarrow only for differences within a narrow box.
template <bool kNarrow>
inline int cross_sign_in(std::int64_t ux, std::int64_t uy, std::int64_t vx,
                         std::int64_t vy) noexcept {
  if constexpr (kNarrow) {
    return cross_sign_narrow(ux, uy, vx, vy);
  } else {
    return cross_sign(ux, uy, vx, vy);
  }
}

// Sign of orient(a, b, c): +1 when c is left of a->b, 0 when collinear.
inline int orient_sign(Point64 a, Point64 b, Point64 c) noexcept {
  return cross_sign(coord_diff(b.x, a.x), coord_diff(b.y, a.y), coord_diff(c.x, a.x),
                    coord_diff(c.y, a.y));
}

}  // namespace edgeland::detail
