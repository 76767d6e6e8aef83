#pragma once
// Perimeter of rings (thesis 2.2, "circumference") as exact integer bounds.
//
// Edge lengths are irrational in general and the kernel uses no floating point, so the
// perimeter is reported as two integers that bracket it: lo <= perimeter <= hi, where lo sums
// floor(|e|) and hi sums ceil(|e|) over the edges e. Both are exact (no rounding error beyond
// the floor/ceil per edge), so hi - lo <= the number of edges whose length is irrational, and
// lo == hi exactly when every edge length is an integer. The clipper's accuracy contract
// (area error <= perimeter) is checked against these bounds.
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

struct PerimeterBounds {
  Int128 lo = 0;  // sum of floor(edge length)
  Int128 hi = 0;  // sum of ceil(edge length)
  friend constexpr bool operator==(const PerimeterBounds&, const PerimeterBounds&) = default;
};

// floor(sqrt(n)) for every unsigned 128-bit n, exactly (digit-by-digit method, no
// floating point). O(1): at most 64 iterations.
EDGELAND_EXPORT UInt128 isqrt(UInt128 n) noexcept;

// Bounds on the ring's perimeter, edge n-1 -> 0 included. A squared edge length is at most
// 2 * (2 kCoordBound)^2 < 2^65 and a length below 2^33, so the sums cannot overflow.
// {0, 0} for fewer than 2 vertices. O(n).
EDGELAND_EXPORT PerimeterBounds perimeter_bounds(const Ring& ring) noexcept;

// Sum of the members' bounds. O(total vertices).
EDGELAND_EXPORT PerimeterBounds perimeter_bounds(const PolygonSet& set) noexcept;

}  // namespace edgeland
