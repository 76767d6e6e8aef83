#include "node.hpp"

#include <algorithm>

#include "state_hash.hpp"

namespace edgeland::detail {

NodePtr make_cell(const Box64& box, std::uint32_t depth, LabeledSet content,
                  std::vector<PolygonId> ids, PolygonId region_next) {
  auto node = std::make_shared<Node>();
  node->box = box;
  node->depth = depth;
  node->deepest = depth;
  node->cells = 1;
  const PolygonSet& polys = content.set.polygons();
  node->boxes.reserve(polys.size());
  StateHash h;
  h.add(box).add(std::uint64_t{0}).add(static_cast<std::uint64_t>(polys.size()));
  for (std::size_t i = 0; i < polys.size(); ++i) {
    node->boxes.push_back(*bounding_box(polys[i]));
    node->vertices += polys[i].size();
    h.add(static_cast<std::uint64_t>(ids[i])).add(static_cast<std::uint64_t>(content.labels[i]));
    h.add(static_cast<std::uint64_t>(polys[i].size()));
    for (Point64 p : polys[i]) h.add(p);
  }
  node->polygons = polys.size();
  if (region_next != 0) h.add(static_cast<std::uint64_t>(region_next));
  node->region_next = region_next;
  node->hash = h.value();
  node->content = std::move(content);
  node->ids = std::move(ids);
  return node;
}

NodePtr make_inner(const Box64& box, std::uint32_t depth, const std::vector<NodePtr>& children,
                   PolygonId region_next) {
  auto node = std::make_shared<Node>();
  node->box = box;
  node->depth = depth;
  node->child_count = static_cast<std::uint32_t>(children.size());
  StateHash h;
  h.add(box).add(static_cast<std::uint64_t>(children.size()));
  for (std::size_t i = 0; i < children.size(); ++i) {
    const NodePtr& c = children[i];
    node->children[i] = c;
    node->polygons += c->polygons;
    node->vertices += c->vertices;
    node->cells += c->cells;
    node->deepest = std::max(node->deepest, c->deepest);
    h.add(c->hash);
  }
  if (region_next != 0) h.add(static_cast<std::uint64_t>(region_next));
  node->region_next = region_next;
  node->hash = h.value();
  const Box64& first = children.front()->box;
  node->cut_x = first.max.x != box.max.x;
  node->cut_y = first.max.y != box.max.y;
  node->x_line = first.max.x;
  node->y_line = first.max.y;
  return node;
}

NodePtr make_stub(const Box64& box, std::uint32_t depth, const RegionSummary& summary) {
  auto node = std::make_shared<Node>();
  node->box = box;
  node->depth = depth;
  node->polygons = summary.polygons;
  node->vertices = summary.vertices;
  node->cells = summary.cells;
  node->deepest = summary.deepest;
  node->hash = summary.hash;
  node->region_next = summary.next_id;
  node->stub = std::make_shared<const StubInfo>(
      StubInfo{summary.path, summary.twice_areas, summary.min_id, summary.max_id});
  return node;
}

}  // namespace edgeland::detail
