// A big shape cut to the cells it touches (shape_cut.hpp).
#include "shape_cut.hpp"

#include <vector>

namespace edgeland::detail {
namespace {

// The cells an edit with this shape box descends into, in tree order.
void touched_cells(const NodePtr& node, const Box64& shape_box, std::vector<const Node*>& out) {
  if (!node->box.overlaps_open(shape_box) || node->is_stub()) return;
  if (node->is_cell()) {
    out.push_back(node.get());
    return;
  }
  for (std::uint32_t i = 0; i < node->child_count; ++i)
    touched_cells(node->children[i], shape_box, out);
}

// Whether the members reaching the cells (by box, as each cell's overlay takes them) add up to
// at least `enough` vertices.
bool reach_at_least(const std::vector<const Node*>& cells, const ValidSet& shape,
                    std::size_t enough) {
  const PolygonSet& members = shape.polygons();
  std::vector<Box64> boxes;
  boxes.reserve(members.size());
  for (const Polygon& m : members) boxes.push_back(*bounding_box(m));
  std::size_t reach = 0;
  for (const Node* cell : cells)
    for (std::size_t k = 0; k < members.size(); ++k) {
      if (!boxes[k].overlaps(cell->box)) continue;
      reach += members[k].size();
      if (reach >= enough) return true;
    }
  return false;
}

}  // namespace

std::optional<ShapeCut> cut_shape_to_cells(const NodePtr& root, const ValidSet& shape,
                                           const Box64& shape_box, const ClipOptions& options) {
  std::size_t vertices = 0;
  for (const Polygon& m : shape.polygons()) vertices += m.size();
  if (vertices < kCutFromVertices) return std::nullopt;
  std::vector<const Node*> cells;
  touched_cells(root, shape_box, cells);
  if (cells.size() < 2 || !reach_at_least(cells, shape, kCutFactor * vertices)) return std::nullopt;
  std::vector<Box64> windows;
  windows.reserve(cells.size());
  for (const Node* cell : cells) windows.push_back(cell->box);
  const std::vector<RegionLabel> labels(shape.polygons().size(), 1);
  std::vector<LabeledSet> parts = cut_to_windows(shape, labels, windows, options);
  ShapeCut cut;
  cut.pieces.reserve(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
    cut.pieces.emplace(cells[i], std::move(parts[i].set));
  return cut;
}

}  // namespace edgeland::detail
