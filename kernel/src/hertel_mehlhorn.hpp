#pragma once
// Stage 2 of convex_pieces(): merging triangles into convex pieces (Hertel and Mehlhorn 1983).
#include <cstddef>

#include "piece_mesh.hpp"

namespace edgeland::detail {

// Drops, in half-edge order, every diagonal whose two pieces merge into a convex piece of at
// most max_corners corners. Pieces stay convex and counter-clockwise (their angles at most 180
// degrees) with at most max_corners corners each; a diagonal that stays is essential (dropping
// it would leave an angle above 180 degrees) or joins pieces too large to merge. O(n log n).
void merge_convex_pieces(PieceMesh& mesh, std::size_t max_corners);

}  // namespace edgeland::detail
