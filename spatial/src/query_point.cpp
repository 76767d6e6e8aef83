// Queries that descend the tree (spatial/README.md, "Queries"): material_at, polygons_in,
// overlaps, stats.
#include <algorithm>
#include <bitset>

#include "edgeland/kernel/box_queries.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "landscape_access.hpp"
#include "node.hpp"

namespace edgeland {
namespace {

using detail::Node;
using detail::NodePtr;

bool open_overlap(const Box64& a, const Box64& b) {
  return a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y;
}

template <class F>
bool visit_cells_meeting(const NodePtr& n, const Box64& box, bool open, F&& f) {
  if (open ? !open_overlap(n->box, box) : !n->box.overlaps(box)) return true;
  if (n->is_cell()) return f(*n);
  for (std::uint32_t i = 0; i < n->child_count; ++i)
    if (!visit_cells_meeting(n->children[i], box, open, f)) return false;
  return true;
}

// A closed box with min > max holds no point, so it meets nothing.
bool inverted(const Box64& box) { return box.min.x > box.max.x || box.min.y > box.max.y; }

std::vector<Material> sorted_materials(const std::bitset<kMaterialCount>& found) {
  std::vector<Material> out;
  for (std::size_t m = 1; m < kMaterialCount; ++m)
    if (found[m]) out.push_back(static_cast<Material>(m));
  return out;
}

}  // namespace

Material Landscape::material_at(Point64 p) const {
  // p + eps (1, eps) lies in the world only if p is in its half-open box.
  if (p.x < s_.world.min.x || p.y < s_.world.min.y || p.x >= s_.world.max.x ||
      p.y >= s_.world.max.y)
    return kEmpty;
  const Node* n = s_.root.get();
  while (!n->is_cell()) n = &n->child_at(p);
  const PolygonSet& polys = n->polygon_set();
  for (std::size_t i = 0; i < polys.size(); ++i) {
    const Box64& b = n->boxes[i];
    // p + eps (1, eps) is in the closed box only if p.x < max.x and p.y < max.y.
    if (p.x < b.min.x || p.y < b.min.y || p.x >= b.max.x || p.y >= b.max.y) continue;
    if (inside_half_open(p, polys[i])) return n->material(i);
  }
  return kEmpty;
}

void Landscape::polygons_in(const Box64& box,
                            const std::function<bool(const PolygonView&)>& visit) const {
  if (inverted(box)) return;
  visit_cells_meeting(s_.root, box, false, [&](const Node& cell) {
    for (std::size_t i = 0; i < cell.ids.size(); ++i) {
      if (!cell.boxes[i].overlaps(box)) continue;
      const PolygonView v{cell.ids[i], cell.material(i), &cell.polygon_set()[i], cell.box};
      if (!visit(v)) return false;
    }
    return true;
  });
}

void Landscape::cells_in(const Box64& box,
                         const std::function<bool(const CellView&)>& visit) const {
  if (inverted(box)) return;
  visit_cells_meeting(s_.root, box, false, [&](const Node& cell) {
    return visit(CellView{cell.box, cell.depth, cell.polygons, cell.vertices});
  });
}

std::vector<Material> Landscape::overlaps(const Box64& box) const {
  // The exact tests below compute with the corners: they must be in range.
  for (const Point64 corner : {box.min, box.max})
    if (!in_range(corner)) throw CoordinateOutOfRange(Operand::kQuery, 0, 0, kNone, corner);
  std::bitset<kMaterialCount> found;
  if (box.min.x >= box.max.x || box.min.y >= box.max.y) return {};
  visit_cells_meeting(s_.root, box, true, [&](const Node& cell) {
    for (std::size_t i = 0; i < cell.ids.size(); ++i) {
      const std::uint32_t m = cell.content.labels[i];
      if (found[m] || !open_overlap(cell.boxes[i], box)) continue;
      if (interiors_overlap(box, cell.polygon_set()[i])) found[m] = true;
    }
    return true;
  });
  return sorted_materials(found);
}

std::vector<Material> Landscape::overlaps(const ValidSet& shape) const {
  std::bitset<kMaterialCount> found;
  for (const Polygon& s : shape.polygons()) {
    const Box64 sb = *bounding_box(s);
    visit_cells_meeting(s_.root, sb, true, [&](const Node& cell) {
      for (std::size_t i = 0; i < cell.ids.size(); ++i) {
        const std::uint32_t m = cell.content.labels[i];
        if (found[m] || !open_overlap(cell.boxes[i], sb)) continue;
        // Two valid polygons overlap exactly when the pair is not a valid set (validate.hpp).
        const ValidationReport r = validate(PolygonSet{cell.polygon_set()[i], s}, 1);
        if (!r.ok() && r.violations.front().rule == Rule::kOverlappingInteriors) found[m] = true;
      }
      return true;
    });
  }
  return sorted_materials(found);
}

LandscapeStats Landscape::stats() const {
  LandscapeStats s;
  s.polygons = s_.root->polygons;
  s.vertices = s_.root->vertices;
  s.cells = s_.root->cells;
  s.depth = s_.root->deepest;
  // Memory: every node once, its content's arrays by capacity.
  std::vector<const Node*> stack{s_.root.get()};
  while (!stack.empty()) {
    const Node* n = stack.back();
    stack.pop_back();
    s.bytes += sizeof(Node);
    for (std::uint32_t i = 0; i < n->child_count; ++i) stack.push_back(n->children[i].get());
    const PolygonSet& polys = n->polygon_set();
    s.bytes += polys.capacity() * sizeof(Polygon) + n->ids.capacity() * sizeof(PolygonId) +
               n->boxes.capacity() * sizeof(Box64) +
               n->content.labels.capacity() * sizeof(RegionLabel);
    for (const Polygon& p : polys) s.bytes += p.capacity() * sizeof(Point64);
  }
  return s;
}

}  // namespace edgeland
