#pragma once
// Exact decomposition of a valid polygon into convex pieces: the collision shapes of a physics
// engine (Box2D's b2PolygonShape takes convex polygons of at most b2_maxPolygonVertices = 8).
#include <cstddef>
#include <vector>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/triangulate.hpp"

namespace edgeland {

// Box2D 2.4's b2_maxPolygonVertices: convex_pieces()'s default bound on a piece's vertices.
inline constexpr std::size_t kDefaultMaxPieceVertices = 8;

// Decomposes a valid polygon (validate(polygon) passes; straight vertices allowed) into convex
// pieces of at most max_vertices vertices each (any value >= 3).
//
// Guarantees, all exact (integer predicates only):
//   * every piece is strictly convex and counter-clockwise: it turns strictly left at every
//     vertex, so it has no straight, collinear or repeated vertex; 3 <= size <= max_vertices;
//   * every piece vertex is a vertex of the polygon (a straight vertex of the polygon may lie
//     inside a piece's edge, where two pieces meet it or along the polygon's boundary);
//   * interiors pairwise disjoint, union exactly the polygon: the twice-areas sum to
//     twice_signed_area(polygon); every piece has area >= 1/2 (a union of lattice triangles);
//   * it never fails on a valid polygon (spikes, one-unit slivers, combs, 10^5 vertices): every
//     triangle of triangulate() is a valid piece, and merging only ever keeps pieces valid;
//   * deterministic: the same pieces, in the same order, on every platform.
//
// Method: Hertel-Mehlhorn over triangulate()'s triangles. Each diagonal between two pieces is
// dropped when the merged piece stays convex (angles at both ends of the diagonal at most 180
// degrees) and has at most max_vertices corners (straight vertices are not counted; they are
// left out of the output). Every remaining diagonal is then essential or joins pieces too large
// to merge; without the size bound the count is at most 4 times the optimum (Hertel and
// Mehlhorn 1983). bench/README.md compares the counts with CGAL's partitions.
//
// Box2D 2.4 (b2PolygonShape::Set, measured with Debian's 2.4.1, bench/box2d_piece_limits and
// bench/README.md): Set recomputes the hull by gift wrapping in float. A piece comes through
// exactly (m_count == size, the same vertices) when its extent D (larger side of its box) and
// reach M (largest |coordinate| relative to the engine's origin), both in units, satisfy
// D (M + D) <= 2^22: no piece was altered there, not even those whose every corner turns by the
// lattice's least angle (area-1/2 slivers, 7-edge arcs); the first losses appear near 2^23, and
// beyond that Debian's Box2D (built with assertions) can abort inside Set. Each unit must be at
// least b2_linearSlop (0.005 m) so that Set's welding keeps distinct points apart. All 35,851
// pieces of the 8192 x 8192 demo world come through with the world's corner as origin (largest
// D (M + D) 2.2e6); a larger world should give its bodies origins near their pieces (a cell's
// corner keeps M below the cell's size).
//
// O(n log n). Throws InvalidArgument when max_vertices < 3, InvalidInput (operand kPolygon;
// CoordinateOutOfRange for a coordinate beyond kCoordBound) for an invalid polygon, and
// TooManyVertices beyond kMaxPolygonAlgorithmVertices (2^30) vertices (triangulate.hpp).
EDGELAND_EXPORT std::vector<Polygon> convex_pieces(
    const Polygon& polygon, std::size_t max_vertices = kDefaultMaxPieceVertices);

// A polygon's triangles and its convex pieces together: exactly triangulate(polygon) and
// convex_pieces(polygon, max_vertices), for one validation and, when the polygon has no straight
// vertex (an operation's output never has), one triangulation instead of two: a debris body's
// fixtures and its render mesh. The same errors as convex_pieces().
struct TrianglesAndPieces {
  std::vector<Triangle> triangles;
  std::vector<Polygon> pieces;
};
EDGELAND_EXPORT TrianglesAndPieces triangles_and_convex_pieces(
    const Polygon& polygon, std::size_t max_vertices = kDefaultMaxPieceVertices);

}  // namespace edgeland
