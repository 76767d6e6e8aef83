#pragma once
// Exact triangulation of a valid polygon: the render mesh of the game layer and the first step of
// convex_pieces (convex_pieces.hpp).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

// The most vertices triangulate() and convex_pieces() accept: their vertex, side and half-edge
// numbers (up to 3n) are 32-bit.
inline constexpr std::size_t kMaxPolygonAlgorithmVertices = std::size_t{1} << 30;

// Indices into the polygon's vertices, counter-clockwise.
struct Triangle {
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  std::uint32_t c = 0;
  friend constexpr bool operator==(const Triangle&, const Triangle&) = default;
};

// Triangulates a valid polygon (validate(polygon) passes: strictly simple, counter-clockwise,
// no holes; consecutive collinear vertices are allowed) using only its own vertices.
//
// Guarantees, all exact (integer predicates only, no floating point):
//   * exactly n - 2 triangles for n vertices;
//   * every triangle counter-clockwise with positive area: none is degenerate, because no
//     diagonal passes through a vertex and no triangle has three collinear corners (a straight
//     vertex of the polygon is always a corner of a triangle whose other corners lie off its
//     line);
//   * interiors pairwise disjoint and their union the polygon: the twice-areas sum to
//     twice_signed_area(polygon);
//   * deterministic: the same triangles in the same order on every platform and compiler.
//
// Method (de Berg et al., Computational Geometry, ch. 3): a sweep adds diagonals that cut the
// polygon into y-monotone pieces, and each piece is triangulated by one pass over its two chains
// with a stack. Ties in y are broken by x (the order of the plane turned by an infinitesimal
// angle), which is how horizontal edges and collinear vertices are handled without special cases;
// kernel/README.md has the invariants and why no triangle can be degenerate.
//
// O(n log n) time, O(n) memory. Throws InvalidInput (operand kPolygon; CoordinateOutOfRange for a
// coordinate beyond kCoordBound) when validate(polygon) reports a violation, and TooManyVertices
// beyond kMaxPolygonAlgorithmVertices (2^30) vertices.
EDGELAND_EXPORT std::vector<Triangle> triangulate(const Polygon& polygon);

}  // namespace edgeland
