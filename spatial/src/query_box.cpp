// The box queries (spatial/README.md, "Queries"): polygons_in, cells_in and overlaps visit the
// cells whose boxes meet the query's, descending only into nodes that meet it.
#include <bitset>

#include "edgeland/kernel/box_queries.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "node.hpp"
#include "query_args.hpp"
#include "regions.hpp"

namespace edgeland {
namespace {

using detail::Node;
using detail::NodePtr;

bool meets(const Box64& node_box, const Box64& box, bool open) {
  return open ? node_box.overlaps_open(box) : node_box.overlaps(box);
}

// n meets the box. A child is read only when its box (from n's cut lines) meets it too: a
// small query reads one path and its neighbours, not every sibling along the way.
template <class F>
bool visit_meeting_cells_below(const NodePtr& n, const Box64& box, bool open, F&& f) {
  detail::require_loaded(*n);
  if (n->is_cell()) return f(n);
  for (std::uint32_t i = 0; i < n->child_count; ++i)
    if (meets(n->child_box(i), box, open) &&
        !visit_meeting_cells_below(n->children[i], box, open, f))
      return false;
  return true;
}

template <class F>
bool visit_cells_meeting(const NodePtr& n, const Box64& box, bool open, F&& f) {
  return !meets(n->box, box, open) || visit_meeting_cells_below(n, box, open, f);
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

void Landscape::polygons_in(const Box64& box,
                            const std::function<bool(const PolygonView&)>& visit) const {
  detail::require_query_box(box);
  if (inverted(box)) return;
  visit_cells_meeting(s_.root, box, false, [&](const NodePtr& cell) {
    for (std::size_t i = 0; i < cell->ids.size(); ++i) {
      if (!cell->boxes[i].overlaps(box)) continue;
      // The view shares the cell: its polygon outlives any later edit (types.hpp).
      const PolygonView v{cell->ids[i], cell->material(i),
                          std::shared_ptr<const Polygon>(cell, &cell->polygon_set()[i]), cell->box};
      if (!visit(v)) return false;
    }
    return true;
  });
}

void Landscape::cells_in(const Box64& box,
                         const std::function<bool(const CellView&)>& visit) const {
  detail::require_query_box(box);
  if (inverted(box)) return;
  visit_cells_meeting(s_.root, box, false, [&](const NodePtr& cell) {
    return visit(CellView{cell->box, cell->depth, cell->polygons, cell->vertices});
  });
}

std::vector<Material> Landscape::overlaps(const Box64& box) const {
  detail::require_query_box(box);
  std::bitset<kMaterialCount> found;
  if (box.min.x >= box.max.x || box.min.y >= box.max.y) return {};
  visit_cells_meeting(s_.root, box, true, [&](const NodePtr& c) {
    const Node& cell = *c;
    for (std::size_t i = 0; i < cell.ids.size(); ++i) {
      const std::uint32_t m = cell.content.labels[i];
      if (found[m] || !cell.boxes[i].overlaps_open(box)) continue;
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
    visit_cells_meeting(s_.root, sb, true, [&](const NodePtr& c) {
      const Node& cell = *c;
      for (std::size_t i = 0; i < cell.ids.size(); ++i) {
        const std::uint32_t m = cell.content.labels[i];
        if (found[m] || !cell.boxes[i].overlaps_open(sb)) continue;
        // Two valid polygons overlap exactly when the pair is not a valid set (validate.hpp).
        const ValidationReport r = validate(PolygonSet{cell.polygon_set()[i], s}, 1);
        if (!r.ok() && r.violations.front().rule == Rule::kOverlappingInteriors) found[m] = true;
      }
      return true;
    });
  }
  return sorted_materials(found);
}

}  // namespace edgeland
