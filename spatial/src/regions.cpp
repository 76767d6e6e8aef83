#include "regions.hpp"

#include <algorithm>
#include <map>

#include "edgeland/kernel/area.hpp"
#include "edgeland/spatial/errors.hpp"
#include "tree_paths.hpp"

namespace edgeland::detail {
namespace {

void collect(const NodePtr& n, std::uint32_t depth, TreePath& path, std::vector<RegionRef>& out) {
  if (n->depth == depth) {
    out.push_back({path, n});
    return;
  }
  for (std::uint32_t i = 0; i < n->child_count; ++i) {
    path.push_back(static_cast<std::uint8_t>(i));
    collect(n->children[i], depth, path, out);
    path.pop_back();
  }
}

}  // namespace

std::uint64_t region_index(const TreePath& path) noexcept {
  std::uint64_t index = 0;
  for (const std::uint8_t i : path) index = index * 4 + i;
  return index;
}

std::vector<RegionRef> regions_of(const NodePtr& root, const LandscapeConfig& config) {
  std::vector<RegionRef> out;
  if (!regions_on(config)) return out;
  TreePath path;
  collect(root, static_cast<std::uint32_t>(config.region_depth), path, out);
  return out;
}

RegionSummary summarize(const NodePtr& region, const TreePath& path, std::uint64_t world_hash) {
  RegionSummary s{path,
                  world_hash,
                  region->hash,
                  region->polygons,
                  region->vertices,
                  region->cells,
                  region->deepest,
                  0,
                  0,
                  region->region_next,
                  {}};
  if (region->is_stub()) {
    s.min_id = region->stub->min_id;
    s.max_id = region->stub->max_id;
    s.twice_areas = region->stub->twice_areas;
    return s;
  }
  std::map<RegionLabel, Int128> areas;  // labels are materials 1..255 (I1)
  for_each_cell(region, [&](const NodePtr& c) {
    for (std::size_t i = 0; i < c->ids.size(); ++i) {
      areas[c->content.labels[i]] += twice_signed_area(c->polygon_set()[i]);
      s.min_id = s.min_id == 0 ? c->ids[i] : std::min(s.min_id, c->ids[i]);
      s.max_id = std::max(s.max_id, c->ids[i]);
    }
  });
  for (const auto& [m, a] : areas) s.twice_areas.emplace_back(static_cast<std::uint8_t>(m), a);
  return s;
}

NodePtr region_at(const NodePtr& root, const LandscapeConfig& config, const TreePath& path) {
  if (!regions_on(config) || path.size() != static_cast<std::size_t>(config.region_depth))
    return nullptr;
  const std::vector<NodePtr> chain = nodes_on(root, path);
  return chain.empty() ? nullptr : chain.back();
}

RegionHere region_above(const NodePtr& root, const LandscapeConfig& config, Point64 p) {
  if (!regions_on(config)) return {};
  RegionHere here{root, 0};
  while (here.node->depth < static_cast<std::uint32_t>(config.region_depth) &&
         here.node->child_count > 0) {
    const Node& n = *here.node;
    const std::uint32_t ix = n.cut_x && p.x >= n.x_line ? 1 : 0;
    const std::uint32_t iy = n.cut_y && p.y >= n.y_line ? 1 : 0;
    const std::uint32_t i = ix + (n.cut_x ? 2 : 1) * iy;
    here.index = here.index * 4 + i;
    here.node = n.children[i];
  }
  return here;
}

void check_region_counter(const Node& region, std::uint64_t index, const std::string& name,
                          std::vector<std::string>& problems) {
  const PolygonId c = region.region_next;
  if (c < region_first_id(index) || c > region_id_end(index))
    problems.push_back(name + ": id counter " + std::to_string(c) + " outside region " +
                       std::to_string(index) + "'s id space");
}

void check_region_ids(const std::vector<PolygonId>& ids, std::uint64_t index, PolygonId counter,
                      const std::string& name, std::vector<std::string>& problems) {
  for (const PolygonId id : ids)
    if (region_of_id(id) != index || id >= counter)
      problems.push_back(name + ": id " + std::to_string(id) + " not below region " +
                         std::to_string(index) + "'s counter in its space");
}

void require_loaded(const Node& node) {
  if (node.is_stub()) throw RegionNotLoaded(node.stub->path, node.box);
}

}  // namespace edgeland::detail
