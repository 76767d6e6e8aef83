// Landscape::cell and the CellContents view (landscape.hpp): a cell found by its box, read as
// arrays.
#include <algorithm>

#include "edgeland/spatial/landscape.hpp"
#include "node.hpp"
#include "regions.hpp"

namespace edgeland {

const Box64& CellContents::box() const noexcept { return cell_->box; }
std::size_t CellContents::size() const noexcept { return cell_->ids.size(); }
std::span<const Polygon> CellContents::polygons() const noexcept { return cell_->polygon_set(); }
std::span<const PolygonId> CellContents::ids() const noexcept { return cell_->ids; }
const ValidSet& CellContents::set() const noexcept { return cell_->content.set; }
std::span<const Box64> CellContents::bounds() const noexcept { return cell_->boxes; }
Material CellContents::material(std::size_t i) const noexcept {
  return static_cast<std::uint8_t>(cell_->content.labels[i]);
}

// A descent by the box's lower-left corner: the only node that can have this box is on that
// path (the children of a node split its box; a child's box never equals an ancestor's).
std::optional<CellContents> Landscape::cell(const Box64& box) const {
  const detail::NodePtr* n = &s_.root;
  while (!((*n)->box == box)) {
    const detail::Node& node = **n;
    if (!node.box.contains(box.min)) return std::nullopt;
    detail::require_loaded(node);
    if (node.is_cell()) return std::nullopt;
    const detail::Node& child = node.child_at(box.min);
    n = &*std::find_if(node.children.begin(), node.children.end(),
                       [&](const detail::NodePtr& c) { return c.get() == &child; });
  }
  detail::require_loaded(**n);
  if (!(*n)->is_cell()) return std::nullopt;
  return CellContents(*n);
}

}  // namespace edgeland
