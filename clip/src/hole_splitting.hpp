#pragma once
// Hole splitting (thesis 3.6.3): a region given by counter-clockwise outer rings and clockwise
// holes becomes hole-free strictly simple polygons, cut along diagonals between existing
// vertices (no new rounding). See clip/README.md for why the cuts leave no hole behind.
#include <cstddef>
#include <vector>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// Each hole must lie inside one of the outers (a region boundary from assembly). Returns the
// outers without holes unchanged and every outer with holes cut into pieces. Adds the number
// of holes removed to `holes_split`. O(h * n) for h holes and n vertices of their polygons.
std::vector<Ring> split_holes(std::vector<Ring> outers, std::vector<Ring> holes,
                              std::size_t& holes_split);

}  // namespace edgeland::detail
