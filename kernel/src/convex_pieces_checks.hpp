#pragma once
// The checker of convex_pieces()'s result (STYLE.md: a checker for every invariant a stage hands
// on); convex_pieces() runs it when EDGELAND_ASSERTS_ENABLED (the test and checked builds).
#include <cstddef>
#include <vector>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// Every piece has 3..max_vertices vertices and turns strictly left at each (strictly convex,
// counter-clockwise, once around: its x-direction changes sign twice), and the twice-areas sum
// to the polygon's. Throws through fail_stage otherwise. O(n).
void check_convex_pieces(const Polygon& polygon, const std::vector<Polygon>& pieces,
                         std::size_t max_vertices);

}  // namespace edgeland::detail
