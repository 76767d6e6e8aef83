#pragma once
// CGAL 5.5 peers of triangulate() and convex_pieces() (cgal_pieces.cpp, its own translation
// unit: CGAL is slow to compile). Epick: the inputs are integers below 2^31, exact in double,
// and neither algorithm constructs new points.
#include <cstddef>
#include <vector>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::bench {

// Constrained Delaunay triangulation of the polygon's vertices with its edges as constraints
// (CGAL::Constrained_Delaunay_triangulation_2, Exact_predicates_tag); the faces inside the
// polygon are found by a flood fill from the infinite face across constraints (CGAL's
// "mark domains" example), as a user would. Returns the number of faces inside.
std::size_t cgal_cdt_inside_faces(const Polygon& polygon);

enum class CgalPartition { kApprox, kGreene, kOptimal };

// The number of convex pieces CGAL's approx_convex_partition_2 (Hertel-Mehlhorn over a
// triangulation), greene_approx_convex_partition_2 (Greene's monotone pieces, then optimal per
// piece) or optimal_convex_partition_2 (Greene's O(n^4) dynamic programme) gives for the
// polygon (counter-clockwise, no straight vertices).
std::size_t cgal_convex_partition(const Polygon& polygon, CgalPartition kind);

}  // namespace edgeland::bench
