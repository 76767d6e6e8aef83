#pragma once
// Big shapes (issue 27, point 6): comb sets of one-unit teeth over many cells of a 4096 x 4096
// world, the shape of a level's stencil or a large fill a game makes in one call. A comb is a
// base bar with `teeth` teeth, each one unit wide and one unit from the next, 250 high; combs
// are stacked across the world, each 4 + 4 * teeth vertices.
#include <cstddef>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/bbox.hpp"

namespace edgeland::bench {

inline constexpr Box64 kBigShapeWorld{{0, 0}, {4096, 4096}};

// The comb set of about `vertices` vertices (one comb per 8,164): 1,000 is one comb of 249
// teeth, 10,000 two of 1,249, 106,000 thirteen of 2,037 (105,976 vertices: the 106k-vertex
// set of issue 27).
ValidSet comb_set(std::size_t vertices);

}  // namespace edgeland::bench
