#pragma once
// triangulate() without the input check, for convex_pieces(), which has checked the polygon.
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/triangulate.hpp"

namespace edgeland::detail {

// The triangles of triangulate() for a polygon that validate() accepts (not checked here).
std::vector<Triangle> triangulate_valid(const Polygon& polygon);

// Throws what triangulate() throws for an invalid polygon (InvalidInput, TooManyVertices).
void require_valid_polygon(const Polygon& polygon);

}  // namespace edgeland::detail
