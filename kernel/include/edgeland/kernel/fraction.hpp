#pragma once
// Exact fractions of 128-bit integers and their exact comparison.
//
// Parameters along rays and edges are quotients of cross products; with |c| <= kCoordBound
// each of those products is below 2^65, so cross-multiplying two of them needs up to 130
// bits and does NOT fit Int128. compare() therefore multiplies into 256 bits (two 128-bit
// halves) and is exact for every Int128 numerator and every positive Int128 denominator.
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/int128.hpp"

namespace edgeland {

// The value num / den. Invariant: den > 0. Not reduced: 1/2 and 2/4 are different objects
// that compare equal; use compare(), not ==, for values.
struct Fraction {
  Int128 num = 0;
  Int128 den = 1;
};

// Sign of a - b: -1, 0 or 1. Exact for all num and all den > 0. O(1).
EDGELAND_EXPORT int compare(const Fraction& a, const Fraction& b) noexcept;

// The full 256-bit product of two unsigned 128-bit numbers, as (high, low) halves. O(1).
struct UInt256 {
  UInt128 hi = 0;
  UInt128 lo = 0;
  friend constexpr bool operator==(const UInt256&, const UInt256&) = default;
  friend constexpr auto operator<=>(const UInt256&, const UInt256&) = default;
};
EDGELAND_EXPORT UInt256 multiply_wide(UInt128 a, UInt128 b) noexcept;

}  // namespace edgeland
