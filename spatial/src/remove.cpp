// Landscape::remove (landscape.hpp): polygons named by id and cell, carved out with each cell's
// own polygons as its piece of the shape (shape_cut.hpp): no shape to validate, no crossing to
// round.
#include <algorithm>
#include <unordered_map>

#include "edgeland/spatial/landscape.hpp"
#include "edgeland/spatial/log_format.hpp"
#include "edit.hpp"
#include "regions.hpp"

namespace edgeland {
namespace {

using detail::Node;
using detail::NodePtr;

// Where the descent to the cell with exactly this box stops: that cell, the stub of an unloaded
// region on the way, or null (no cell has this box).
const Node* cell_with_box(const NodePtr& root, const Box64& box) {
  const Node* n = root.get();
  while (!(n->box == box) && !n->is_stub()) {
    if (n->is_cell() || !n->box.contains(box.min)) return nullptr;
    n = &n->child_at(box.min);
  }
  return n->is_cell() || n->is_stub() ? n : nullptr;
}

// Each named polygon's index in its cell, per cell (ascending, once each). A name in an unloaded
// region is refused (RegionNotLoaded), or left out under UnloadedRegions::kSkip as an edit
// leaves a stub.
std::unordered_map<const Node*, std::vector<std::size_t>> locate(
    const NodePtr& root, std::span<const PolygonRef> polygons, UnloadedRegions unloaded) {
  std::unordered_map<const Node*, std::vector<std::size_t>> out;
  for (const PolygonRef& p : polygons) {
    const Node* cell = cell_with_box(root, p.cell);
    if (cell == nullptr) throw UnknownPolygon(p.id, p.cell);
    if (cell->is_stub() && unloaded == UnloadedRegions::kSkip) continue;
    detail::require_loaded(*cell);
    const auto at = std::find(cell->ids.begin(), cell->ids.end(), p.id);
    if (at == cell->ids.end()) throw UnknownPolygon(p.id, p.cell);
    out[cell].push_back(static_cast<std::size_t>(at - cell->ids.begin()));
  }
  for (auto& [cell, members] : out) {
    std::sort(members.begin(), members.end());
    members.erase(std::unique(members.begin(), members.end()), members.end());
  }
  return out;
}

}  // namespace

ChangeSet Landscape::remove(std::span<const PolygonRef> polygons) {
  const auto members = locate(s_.root, polygons, s_.unloaded);
  detail::ShapeCut cut;
  Box64 box;
  std::size_t vertices = 0;
  for (const auto& [cell, indices] : members) {
    ValidSet piece = subset(cell->content.set, indices);
    for (const Polygon& p : piece.polygons()) {
      if (vertices == 0)
        box = *bounding_box(p);
      else
        box.expand(*bounding_box(p));
      vertices += p.size();
    }
    cut.pieces.emplace(cell, std::move(piece));
    cut.members.emplace(cell, indices);
  }
  if (vertices == 0) return {};
  // The log line: a carve of the removed polygons, in a fixed order.
  const auto line = [&] {
    PolygonSet all;
    for (const auto& [cell, indices] : members)
      for (std::size_t i : indices) all.push_back(cell->polygon_set()[i]);
    std::sort(all.begin(), all.end());
    return log::edit_line(log::LandscapeEditKind::kCarve, all);
  };
  static const ValidSet kNothingElse;  // what cells the cut does not reach take: no shape
  const detail::EditTable carve = detail::EditTable::carve();
  const RelabelStep step{&kNothingElse, carve.table};
  const auto build = [&] {
    return detail::EditBuilder(s_, std::span(&step, 1)).build(std::move(cut), box, vertices);
  };
  return apply(build, line);
}

}  // namespace edgeland
