#pragma once
// The nodes of the landscape's persistent PR tree (spatial/README.md): immutable once built,
// shared between snapshots. A leaf is a cell holding a canonical labeled set; an inner node has
// two or four children (cell_split.hpp). Every node keeps the sums of its subtree and the hash
// of its canonical form, so the landscape's counts and state hash cost O(1).
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "edgeland/clip/relabel.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland::detail {

// What an unloaded region keeps besides the sums every node has (Landscape::unload_region).
struct StubInfo {
  TreePath path;
  std::vector<std::pair<Material, Int128>> twice_areas;  // solid materials present, ascending
  PolygonId min_id = 0, max_id = 0;                      // its ids' range (0, 0: none)
};

struct Node {
  Box64 box;
  std::uint32_t depth = 0;        // the root is 0
  std::uint32_t child_count = 0;  // 0 for a cell
  std::array<std::shared_ptr<const Node>, 4> children;
  // Where the children meet (inner nodes): a point at or past a cut line belongs to the high
  // child (the half-open rule), so a descent picks a child by two comparisons without reading
  // the children.
  bool cut_x = false, cut_y = false;
  std::int64_t x_line = 0, y_line = 0;

  // A cell's content: canonical order; labels are materials (1..255).
  LabeledSet content;
  std::vector<PolygonId> ids;
  std::vector<Box64> boxes;  // bounding box of each polygon

  // Sums over the subtree.
  std::size_t polygons = 0, vertices = 0, cells = 0;
  std::uint32_t deepest = 0;  // the largest depth of a cell below (or this one's)
  std::uint64_t hash = 0;
  // A region's id counter (LandscapeConfig::region_ids; part of the hash), else 0.
  PolygonId region_next = 0;
  // Set on an unloaded region: no content and no children, the sums and hash of the region it
  // stands for (a stub is neither a cell nor an inner node; every walk of the tree checks).
  std::shared_ptr<const StubInfo> stub;

  bool is_cell() const noexcept { return child_count == 0 && !stub; }
  bool is_stub() const noexcept { return stub != nullptr; }
  // The child whose half-open box holds p (p in this node's box).
  const Node& child_at(Point64 p) const noexcept {
    const std::uint32_t ix = cut_x && p.x >= x_line ? 1 : 0;
    const std::uint32_t iy = cut_y && p.y >= y_line ? 1 : 0;
    return *children[ix + (cut_x ? 2 : 1) * iy];
  }
  // The box of child i (an inner node), from this node's box and cut lines: a walk picks the
  // children a query meets without reading the others (split_boxes' order: x first).
  Box64 child_box(std::uint32_t i) const noexcept {
    const std::uint32_t ix = cut_x ? i % 2 : 0, iy = cut_x ? i / 2 : i;
    Box64 b = box;
    if (cut_x) (ix == 0 ? b.max.x : b.min.x) = x_line;
    if (cut_y) (iy == 0 ? b.max.y : b.min.y) = y_line;
    return b;
  }
  const PolygonSet& polygon_set() const noexcept { return content.set.polygons(); }
  // The material of polygon i (labels are materials 1..255 by I1).
  Material material(std::size_t i) const { return content.labels[i]; }
};

using NodePtr = std::shared_ptr<const Node>;

// A cell from its content (canonical, inside box) and the ids of its polygons; region_next: its
// id counter when it is a region with its own ids (else 0, and the hash is as without regions).
NodePtr make_cell(const Box64& box, std::uint32_t depth, LabeledSet content,
                  std::vector<PolygonId> ids, PolygonId region_next = 0);
// An inner node over its children (in split_boxes order).
NodePtr make_inner(const Box64& box, std::uint32_t depth, const std::vector<NodePtr>& children,
                   PolygonId region_next = 0);
// The stub of a region (its summary and where it lies).
NodePtr make_stub(const Box64& box, std::uint32_t depth, const RegionSummary& summary);

// Calls f(cell) for every cell below node, in tree order (stubs have none).
template <class F>
void for_each_cell(const NodePtr& node, F&& f) {
  if (node->is_cell()) {
    f(node);
    return;
  }
  for (std::uint32_t i = 0; i < node->child_count; ++i) for_each_cell(node->children[i], f);
}

// Calls f(node) for every node below node and itself, in preorder.
template <class F>
void for_each_node(const NodePtr& node, F&& f) {
  f(node);
  for (std::uint32_t i = 0; i < node->child_count; ++i) for_each_node(node->children[i], f);
}

}  // namespace edgeland::detail
