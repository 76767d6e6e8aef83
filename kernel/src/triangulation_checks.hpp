#pragma once
// The checkers of triangulate()'s stages (STYLE.md: a checker for every invariant a stage hands
// on). Each throws through fail_stage when its invariant is broken; triangulate() runs them when
// EDGELAND_ASSERTS_ENABLED (the test and checked builds).
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/triangulate.hpp"
#include "polygon_faces.hpp"

namespace edgeland::detail {

// Stages 1-2: d diagonals gave d + 1 faces holding n + 2d vertex entries, each face monotone in
// the sweep order (its vertices, from the first in sweep order counter-clockwise to the last
// and on back to the first, change direction in that order exactly twice). O(n + d).
void check_monotone_faces(const Polygon& polygon, std::size_t diagonal_count, const Faces& faces);

// Stage 3: n - 2 triangles of in-range indices, each counter-clockwise with positive area, whose
// twice-areas sum to the polygon's. O(n).
void check_triangles(const Polygon& polygon, const std::vector<Triangle>& triangles);

}  // namespace edgeland::detail
