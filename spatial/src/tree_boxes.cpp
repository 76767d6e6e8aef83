// The tree's geometry for code outside spatial (tree_boxes.hpp): the boxes of a node's children
// and how deep a uniform grid over a world can go, from the split the landscape itself uses.
#include "edgeland/spatial/tree_boxes.hpp"

#include <cstdint>
#include <set>
#include <utility>

#include "cell_split.hpp"

namespace edgeland {

std::vector<Box64> child_boxes(const Box64& node, const LandscapeConfig& config) {
  if (!detail::can_split(node, config)) return {};
  return detail::split_boxes(node, config);
}

int max_grid_depth(const Box64& world, const LandscapeConfig& config) {
  // The boxes of one depth differ only in where they lie; their sizes decide whether they
  // split, so the search keeps one box per (width, height) and splits it as the tree does.
  // Every split halves a side longer than min_cell_size >= 1, so the loop ends (at most about
  // 64 levels for in-range worlds).
  std::set<std::pair<std::int64_t, std::int64_t>> sizes{
      {world.max.x - world.min.x, world.max.y - world.min.y}};
  for (int depth = 0;; ++depth) {
    std::set<std::pair<std::int64_t, std::int64_t>> next;
    for (const auto& [w, h] : sizes) {
      const Box64 box{{0, 0}, {w, h}};
      if (!detail::can_split(box, config)) return depth;
      for (const Box64& child : detail::split_boxes(box, config))
        next.insert({child.max.x - child.min.x, child.max.y - child.min.y});
    }
    sizes = std::move(next);
  }
}

}  // namespace edgeland
