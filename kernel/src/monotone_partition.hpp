#pragma once
// Stage 1 of triangulate(): the diagonals that cut a polygon into monotone pieces.
#include <cstdint>
#include <vector>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// A diagonal between two vertices of a polygon (indices), inside it.
struct Diagonal {
  std::uint32_t from = 0;
  std::uint32_t to = 0;
};

// de Berg et al., ch. 3, MakeMonotone: one sweep in sweeps_before order (sweep_order.hpp) over
// a valid polygon (validate() passes). Returns diagonals whose relative interiors lie in the
// polygon's interior and pairwise do not meet, no two joining the same pair of vertices, which
// cut the polygon into pieces monotone in the sweep order: each piece's boundary is two chains
// from its first vertex to its last, each in sweep order. O(n log n).
std::vector<Diagonal> monotone_diagonals(const Polygon& polygon);

}  // namespace edgeland::detail
