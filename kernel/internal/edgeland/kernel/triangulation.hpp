#pragma once
// triangulate() and triangles_and_convex_pieces() without the input check, for callers that know
// the polygon is valid: convex_pieces(), which has checked it, and the game layer's meshes of a
// landscape's own polygons (valid by the landscape's invariant I1; game/src/landscape_meshes.hpp)
// and debris outlines (merge_tiles' outputs).
#include <vector>

#include "edgeland/kernel/convex_pieces.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/triangulate.hpp"

namespace edgeland::detail {

// The triangles of triangulate() for a polygon that validate() accepts (not checked here).
std::vector<Triangle> triangulate_valid(const Polygon& polygon);

// triangles_and_convex_pieces() of a polygon that validate() accepts (not checked here, but in
// builds with assertions): a debris body's merged outline, an output of merge_tiles.
TrianglesAndPieces triangles_and_convex_pieces_valid(const Polygon& polygon,
                                                     std::size_t max_vertices);

// Throws what triangulate() throws for an invalid polygon (InvalidInput, TooManyVertices).
void require_valid_polygon(const Polygon& polygon);

}  // namespace edgeland::detail
