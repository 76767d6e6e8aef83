#pragma once
// The geometry of the landscape's tree (spatial/README.md, "The model"), for code that keeps
// its own data per node in step with the landscape (the game layer's island summaries): which
// boxes a node's children have. The same function the landscape splits with.
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland {

// The boxes of the children of a node with this box, in the tree's order (x before y, low before
// high), cut at its integer midpoint lines: four (quadtree), two (kd-tree, or a quadtree node
// with one side at most min_cell_size), or none when no side is longer than min_cell_size. O(1).
EDGELAND_EXPORT std::vector<Box64> child_boxes(const Box64& node, const LandscapeConfig& config);

// The deepest uniform grid (LandscapeConfig::grid_depth) the world allows with this
// configuration: a cell splits only while a side is longer than min_cell_size, so below this
// depth some cells would be missing. A deeper grid_depth is refused (InvalidConfig,
// kGridDepthBeyondCells) rather than built shallower. The world must be a valid one (positive
// width and height) and min_cell_size >= 1. O(depth).
EDGELAND_EXPORT int max_grid_depth(const Box64& world, const LandscapeConfig& config);

}  // namespace edgeland
