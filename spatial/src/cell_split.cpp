#include "cell_split.hpp"

#include <string>

#include "edgeland/spatial/tree_boxes.hpp"  // max_grid_depth

namespace edgeland::detail {
namespace {

std::int64_t width(const Box64& b) { return b.max.x - b.min.x; }
std::int64_t height(const Box64& b) { return b.max.y - b.min.y; }
std::int64_t mid(std::int64_t lo, std::int64_t hi) { return lo + (hi - lo) / 2; }

}  // namespace

void require_config(const Box64& world, const LandscapeConfig& c) {
  using Setting = InvalidConfig::Setting;
  auto refuse = [&](Setting setting) { throw InvalidConfig(setting, world, c); };
  if (!in_range(world.min) || !in_range(world.max)) refuse(Setting::kWorldOutOfRange);
  if (world.min.x >= world.max.x || world.min.y >= world.max.y) refuse(Setting::kWorldEmpty);
  if (c.edge_cap < kMinEdgeCap) refuse(Setting::kEdgeCap);
  if (c.merge_below >= c.edge_cap) refuse(Setting::kMergeBelow);
  if (c.min_cell_size < 1) refuse(Setting::kMinCellSize);
  if (c.grid_depth < -1 || c.grid_depth > kMaxGridDepth) refuse(Setting::kGridDepth);
  if (c.tree != TreeKind::kQuadtree && c.tree != TreeKind::kKdTree) refuse(Setting::kTree);
  if (c.grid_depth > max_grid_depth(world, c)) refuse(Setting::kGridDepthBeyondCells);
  if (c.region_depth < -1 || c.region_depth > kMaxGridDepth ||
      c.region_depth > max_grid_depth(world, c) ||
      (c.grid_depth >= 0 && c.region_depth > c.grid_depth))
    refuse(Setting::kRegionDepth);
  if (c.region_ids && c.region_depth < 0) refuse(Setting::kRegionIds);
}

bool can_split(const Box64& box, const LandscapeConfig& config) noexcept {
  return width(box) > config.min_cell_size || height(box) > config.min_cell_size;
}

std::vector<Box64> split_boxes(const Box64& box, const LandscapeConfig& config) {
  bool cut_x = width(box) > config.min_cell_size;
  bool cut_y = height(box) > config.min_cell_size;
  if (config.tree == TreeKind::kKdTree && cut_x && cut_y) {
    cut_x = width(box) >= height(box);
    cut_y = !cut_x;
  }
  std::vector<std::int64_t> xs{box.min.x}, ys{box.min.y};
  if (cut_x) xs.push_back(mid(box.min.x, box.max.x));
  if (cut_y) ys.push_back(mid(box.min.y, box.max.y));
  xs.push_back(box.max.x);
  ys.push_back(box.max.y);
  std::vector<Box64> out;
  for (std::size_t j = 0; j + 1 < ys.size(); ++j)
    for (std::size_t i = 0; i + 1 < xs.size(); ++i)
      out.push_back({{xs[i], ys[j]}, {xs[i + 1], ys[j + 1]}});
  return out;
}

}  // namespace edgeland::detail
