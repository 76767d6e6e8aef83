#pragma once
// The geometry of the landscape's tree (spatial/README.md, "The model"), for code that keeps
// its own data per node in step with the landscape (the game layer's island summaries): which
// boxes a node's children have. The same function the landscape splits with.
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland {

// The boxes of the children of a node with this box, in the tree's order (x before y, low before
// high), cut at its integer midpoint lines: four (quadtree), two (kd-tree, or a quadtree node
// with one side at most min_cell_size), or none when no side is longer than min_cell_size. O(1).
EDGELAND_EXPORT std::vector<Box64> child_boxes(const Box64& node, const LandscapeConfig& config);

}  // namespace edgeland
