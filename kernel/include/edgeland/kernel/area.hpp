#pragma once
// Exact signed area and orientation of rings (thesis 2.2).
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland {

// Twice the signed area of the ring, exactly: the shoelace sum of cross(v_i, v_(i+1)) over
// all n edges (the thesis's Gaussian trapezoid formula, rearranged). Positive for a
// counter-clockwise ring, negative for a clockwise one; for a self-intersecting ring it is
// the winding-number-weighted area. 0 for fewer than 3 vertices.
// Each term is at most 2*kCoordBound^2 < 2^63 in magnitude, so the Int128 sum cannot
// overflow for fewer than about 2^64 vertices (proofs/: area_shoelace_sum_int128).
// O(n).
EDGELAND_EXPORT Int128 twice_signed_area(const Ring& ring) noexcept;

// Sum of twice_signed_area over the members. O(total vertices).
EDGELAND_EXPORT Int128 twice_signed_area(const PolygonSet& set) noexcept;

// The sign of twice_signed_area: kCounterClockwise, kClockwise, or kCollinear for a ring
// of zero area (also for fewer than 3 vertices). O(n).
EDGELAND_EXPORT Orientation ring_orientation(const Ring& ring) noexcept;

}  // namespace edgeland
