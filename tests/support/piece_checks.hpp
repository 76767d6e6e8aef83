#pragma once
// Independent checks of triangulate() and convex_pieces() results (triangulate.hpp,
// convex_pieces.hpp), shared by tests/kernel and the fuzz target. Each returns an empty string
// when every promised property holds, else the first one broken, in words.
#include <cstddef>
#include <string>
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/triangulate.hpp"

namespace edgeland::testing {

// n - 2 triangles of in-range, distinct indices; each counter-clockwise with positive area;
// twice-areas summing to the polygon's; pairwise disjoint interiors (validate() of the triangles
// as a polygon set). O(n log n).
std::string triangulation_defect(const Polygon& polygon, const std::vector<Triangle>& triangles);

// Brute force, O(n) per triangle: every triangle side is a polygon edge or a diagonal whose
// open segment meets no polygon edge and leaves its vertex into the polygon's interior angle,
// so every triangle lies inside the polygon; with triangulation_defect() this makes the union
// exactly the polygon.
std::string diagonal_defect(const Polygon& polygon, const std::vector<Triangle>& triangles);

// Each piece has 3..max_vertices vertices, all of them the polygon's and distinct; turns
// strictly left at every vertex and winds once (strictly convex, counter-clockwise, no straight
// vertex); the pieces' twice-areas sum to the polygon's; pairwise disjoint interiors.
// O(n log n).
std::string convex_pieces_defect(const Polygon& polygon, const std::vector<Polygon>& pieces,
                                 std::size_t max_vertices);

// The union of `parts` is exactly the polygon: their symmetric difference, computed by the
// clipper, is empty (exact here: every vertex of `parts` is a polygon vertex, so no edge crosses
// another and nothing is snapped).
std::string union_defect(const Polygon& polygon, const PolygonSet& parts);

// The triangles as polygons.
PolygonSet triangle_polygons(const Polygon& polygon, const std::vector<Triangle>& triangles);

}  // namespace edgeland::testing
