#pragma once
// The exact centroid (centre of mass at uniform density) of a polygon set: where the game layer
// puts a detached island's body.
#include <cstddef>
#include <cstdint>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland {

// The most vertices, all rings together, centroid() accepts: floor((2^127 - 1) / (4 B^3)) with
// B = kCoordBound, about 2^32 (proofs/: centroid_sums_int128). Each edge adds at most 4 B^3 to a
// moment sum, so the sums stay within Int128 up to this many edges.
// A 64-bit constant: where std::size_t has 32 bits (WebAssembly) it would wrap around to 6, and
// no vector there can hold more vertices than it anyway.
inline constexpr std::uint64_t kMaxCentroidVertices = 4294967302;

// The centroid of the set's area, each ring weighted by its signed area: for a valid polygon set
// (validate(set) passes) the centre of mass of the region it covers. Exact, as a RationalPoint
// in lowest terms (gcd(x_num, y_num, den) == 1) with den > 0:
//   x = sum over all edges a -> b of (a_x + b_x) cross(a, b) / (3 * twice_signed_area(set)),
// likewise y (formulas::moment_term, formulas::centroid_denominator). Rings of fewer than 3
// vertices add nothing, as to twice_signed_area. The set needs no other precondition: the
// formula is the signed-area centroid of any rings.
//
// O(total vertices). Throws CoordinateOutOfRange (operand kPolygon) for a coordinate beyond
// kCoordBound, TooManyVertices beyond kMaxCentroidVertices vertices in all, and NonPositiveArea
// when the total twice-area is not positive (an empty set, rings of no area, clockwise rings).
EDGELAND_EXPORT RationalPoint centroid(const PolygonSet& set);

}  // namespace edgeland
