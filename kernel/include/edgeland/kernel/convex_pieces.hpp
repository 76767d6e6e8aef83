#pragma once
// Exact decomposition of a valid polygon into convex pieces: the collision shapes of a physics
// engine (Box2D's b2PolygonShape takes convex polygons of at most b2_maxPolygonVertices = 8).
#include <cstddef>
#include <vector>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/polygon.hpp"

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
// Box2D: b2PolygonShape::Set recomputes the hull in float and may drop a vertex whose turn is
// too slight for float; see tests/kernel/convex_pieces_box2d_test.cpp and bench/README.md for
// where, at a realistic scale, that happens.
//
// O(n log n). Throws InvalidArgument when max_vertices < 3, InvalidInput (operand kPolygon;
// CoordinateOutOfRange for a coordinate beyond kCoordBound) for an invalid polygon, and
// TooManyVertices beyond 2^32 - 1 vertices.
EDGELAND_EXPORT std::vector<Polygon> convex_pieces(
    const Polygon& polygon, std::size_t max_vertices = kDefaultMaxPieceVertices);

}  // namespace edgeland
