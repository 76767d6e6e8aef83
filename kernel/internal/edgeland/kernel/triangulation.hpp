#pragma once
// triangulate() without the input check, for callers that know the polygon is valid:
// convex_pieces(), which has checked it, and the game layer's meshes of a landscape's own
// polygons (valid by the landscape's invariant I1; game/src/landscape_meshes.hpp).
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/triangulate.hpp"

namespace edgeland::detail {

// The triangles of triangulate() for a polygon that validate() accepts (not checked here).
std::vector<Triangle> triangulate_valid(const Polygon& polygon);

// Throws what triangulate() throws for an invalid polygon (InvalidInput, TooManyVertices).
void require_valid_polygon(const Polygon& polygon);

}  // namespace edgeland::detail
