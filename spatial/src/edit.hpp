#pragma once
// One edit of the landscape as a rebuild of the touched part of the tree (edit.cpp).
#include <functional>
#include <string>
#include <vector>

#include "edgeland/clip/relabel.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "ids.hpp"
#include "node.hpp"
#include "shape_cut.hpp"

namespace edgeland {

// The relabel table of an edit: inside the shape material a becomes table[a] (a >= size: kept).
struct EditTable {
  std::vector<RegionLabel> table;
  static EditTable carve() { return {std::vector<RegionLabel>(kMaterialCount, 0)}; }
  static EditTable fill(Material m) {
    return {std::vector<RegionLabel>(kMaterialCount, m.value())};
  }
  static EditTable fill_empty(Material m) { return {{m.value()}}; }
  static EditTable replace(Material from, Material to) {
    std::vector<RegionLabel> t(kMaterialCount);
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = static_cast<RegionLabel>(i);
    t[from.value()] = to.value();
    return {t};
  }
  static EditTable relabel(const MaterialMap& map) {
    std::vector<RegionLabel> t(kMaterialCount);
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = map[static_cast<std::uint8_t>(i)].value();
    return {t};
  }
};

// Builds the tree after one edit from the landscape's current one, never touching the
// landscape; run() commits at its very end (the strong guarantee).
class LandscapeEditor {
 public:
  LandscapeEditor(const Landscape& l, const ValidSet& shape, EditTable table);
  // log_line makes the edit's line of the edit log (written only when recording, or into an
  // internal error's log).
  ChangeSet run(Landscape& target, const std::function<std::string()>& log_line);

 private:
  // A part of the new tree before it has ids: an old node kept as it is (`kept`), a new cell
  // (`content`), or a new inner node over `children` (split_boxes order). Ids are given only
  // once the new tree's shape is final (finish), so a cell that a split or merge replaces
  // within the edit never takes an id, and every new cell takes its ids from the old cells
  // it covers, not from a cell the edit made and threw away.
  struct Draft {
    detail::NodePtr kept;
    Box64 box;
    std::uint32_t depth = 0;
    LabeledSet content;
    std::vector<Draft> children;
    std::size_t vertices = 0;
    static Draft keep(const detail::NodePtr& node);
    static Draft cell(const Box64& box, std::uint32_t depth, LabeledSet content);
    static Draft inner(const Box64& box, std::uint32_t depth, std::vector<Draft> children);
    bool is_cell() const { return kept ? kept->is_cell() : children.empty(); }
    const LabeledSet& cell_content() const { return kept ? kept->content : content; }
  };

  Draft rebuild(const detail::NodePtr& node);
  Draft edit_cell(const detail::NodePtr& cell);
  // What of the shape a cell's overlay takes: its pieces when the shape was cut to the cells
  // (shape_cut.hpp), else the whole shape.
  const ValidSet& shape_in(const detail::Node& cell) const;
  Draft split_if_needed(Draft cell);
  Draft merge_if_small(const detail::NodePtr& old, std::vector<Draft> children);
  detail::NodePtr finish(Draft& draft, const detail::NodePtr& old);
  detail::NodePtr finish_within(Draft& draft, const detail::IdSource& previous);
  ClipOptions clip_options() const { return ClipOptions{.checked = s_.checked}; }
  // Counts the vertices a new cell adds over what it replaces (and the cells a split adds), and
  // throws LimitExceeded as soon as the landscape could pass its vertex (cell) limit: a runaway
  // split stops early.
  void grow(std::size_t before, std::size_t after);
  void grow_cells(std::size_t added);

  const Landscape& l_;
  const detail::LandscapeState& s_;  // l_'s state
  const ValidSet& shape_;
  EditTable table_;
  Box64 shape_box_;
  PolygonId next_id_;
  std::size_t growth_ = 0;
  std::size_t cell_growth_ = 0;
  std::optional<detail::ShapeCut> cut_;
};

}  // namespace edgeland
