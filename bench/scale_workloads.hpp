#pragma once
// Inputs of the scale benchmarks (issue 16, point 1): large operands whose boundaries cross
// many times, for edgeland and its peers side by side (scale_benchmarks.cpp, run_scale.sh).
// Deterministic: fixed seeds (the kernel's SplitMix64) and std::cos/std::sin + llround in bench/
// only; the library never sees a double. Every operand is checked with edgeland::validate.
#include <cstddef>
#include <cstdint>

#include "workloads.hpp"

namespace edgeland::bench {

// Comb A: the base bar [0, T*80] x [0, h] with T teeth [80k, 80k + 40] x [h, tip], one
// polygon of 4T + 2 vertices. Comb B: A shifted by (20, tip/2), so B's base crosses every
// tooth of A and B's teeth cross A's tooth tips: about 4T crossings, all at integer points
// (no snapping). Requires h < tip/2.
Operands combs(std::size_t teeth, std::int64_t tip, std::int64_t h);

// A star of n vertices at angles 2*pi*i/n, radius alternating 10^8 and 0.9*10^8, and the
// same star rotated by 2*pi*3e-6 and shifted by (1234, -777): every zigzag edge crosses its
// neighbours in the other star, and almost no crossing is an integer point (snapped).
// n must be even.
Operands zigzag_stars(std::size_t n);

// A star of n vertices with seeded random radii in [5*10^7, 10^8] as the subject, and the
// empty set as the clip: what does a trivial operation on a big operand cost?
Operands star_minus_empty(std::size_t n);

}  // namespace edgeland::bench
