#pragma once
// Cosine and sine of a rational fraction of a turn in Q62 fixed point, from integers only: the
// directions of the shape builders' corners (shapes.hpp), the same on every platform.
#include "edgeland/kernel/int128.hpp"

namespace edgeland::detail {

inline constexpr Int128 kFixedOne = Int128{1} << 62;
// pi/4 times 2^62, rounded down (the next bit is 0), from Machin's formula in exact integers.
inline constexpr Int128 kQuarterPiFixed = 3622009729038561421;
// The largest q direction_of_turn takes: kMaxShapeSides times kMaxTurnDenominator (shapes.hpp).
inline constexpr Int128 kMaxTurnParts = Int128{1} << 47;

// cos and sin times kFixedOne, each within 64 units of the exact value (about 2^-56).
struct FixedDirection {
  Int128 c = 0, s = 0;
};

// The direction p / q of a full turn counter-clockwise from +x, 0 <= p < q <= kMaxTurnParts.
// Symmetric: directions mirrored in an axis or a diagonal come out exactly mirrored.
FixedDirection direction_of_turn(Int128 p, Int128 q);

}  // namespace edgeland::detail
