// direction_of_turn (shape_trig.hpp): the turn is reduced to an angle x in [0, pi/4] of one
// octant, whose cosine and sine come from their Taylor series; the octant's symmetry (swaps and
// sign changes, exact) gives the rest.
#include "shape_trig.hpp"

#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"

namespace edgeland::detail {
namespace {

using W = arith::Checked<Int128>;

// cos x and sin x for 0 <= x <= pi/4 in fixed point: the sums of the terms x^j / j!, each from
// the last (formulas::taylor_step), with alternating signs. The terms fall below one unit by
// j = 23 (x^j / j! < 2^-62 there), so the loop ends; each term is floored, so each sum is
// within the number of terms (at most 24) of the exact value.
FixedDirection octant_direction(Int128 x) {
  W term = kFixedOne, c = 0, s = 0;
  for (std::int64_t j = 0; term.v != 0; ++j) {
    const bool negative = (j / 2) % 2 == 1;
    W& sum = j % 2 == 0 ? c : s;
    sum = negative ? sum - term : sum + term;
    term = formulas::taylor_step<W>(term, x, kFixedOne, j + 1);
  }
  return {c.v, s.v};
}

// The direction at octant o (0..7) plus x, where x is measured from the octant's start for even
// o and back from its end for odd o (so every x is in [0, pi/4] and mirrored angles share it).
FixedDirection place_in_octant(std::int64_t o, FixedDirection d) {
  const Int128 c = d.c, s = d.s;
  switch (o) {
    case 0:
      return {c, s};
    case 1:
      return {s, c};
    case 2:
      return {-s, c};
    case 3:
      return {-c, s};
    case 4:
      return {-c, -s};
    case 5:
      return {-s, -c};
    case 6:
      return {s, -c};
    default:
      return {c, -s};
  }
}

}  // namespace

FixedDirection direction_of_turn(Int128 p, Int128 q) {
  EDGELAND_ASSERT(0 <= p && p < q && q <= kMaxTurnParts, "shape directions", "turn out of range");
  const auto octant = static_cast<std::int64_t>(8 * p / q);  // 0..7
  const Int128 rem = 8 * p - octant * q;                     // in [0, q)
  const Int128 within = octant % 2 == 0 ? rem : q - rem;
  const W x = formulas::octant_angle<W>(kQuarterPiFixed, within, q);
  FixedDirection d = octant_direction(x.v);
  // On a diagonal the two series differ in their last unit; one value for both keeps the
  // diagonal directions exact mirrors of each other.
  if (within == q) d.s = d.c;
  return place_in_octant(octant, d);
}

}  // namespace edgeland::detail
