#pragma once
// One edit of the landscape as a rebuild of the touched part of the tree (edit.cpp).
#include <functional>
#include <string>
#include <vector>

#include "edgeland/clip/relabel.hpp"
#include "ids.hpp"
#include "node.hpp"

namespace edgeland {

// The relabel table of an edit: inside the shape material a becomes table[a] (a >= size: kept).
struct EditTable {
  std::vector<RegionLabel> table;
  static EditTable carve() { return {std::vector<RegionLabel>(kMaterialCount, 0)}; }
  static EditTable fill(Material m) { return {std::vector<RegionLabel>(kMaterialCount, m)}; }
  static EditTable fill_empty(Material m) { return {{m}}; }
  static EditTable replace(Material from, Material to) {
    std::vector<RegionLabel> t(kMaterialCount);
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = static_cast<RegionLabel>(i);
    t[from] = to;
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
  detail::NodePtr rebuild(const detail::NodePtr& node);
  detail::NodePtr edit_cell(const detail::NodePtr& cell);
  detail::NodePtr split_if_needed(const detail::NodePtr& cell);
  detail::NodePtr merge_if_small(const detail::NodePtr& inner);
  detail::NodePtr cell_from(const Box64& box, std::uint32_t depth, LabeledSet content,
                            const detail::IdSource& previous);
  ClipOptions clip_options() const { return ClipOptions{.checked = l_.checked_}; }
  // Counts the vertices a new cell adds over what it replaces, and throws LimitExceeded as
  // soon as the landscape could pass its vertex limit (a runaway split stops early).
  void grow(std::size_t before, std::size_t after);

  const Landscape& l_;
  const ValidSet& shape_;
  EditTable table_;
  Box64 shape_box_;
  PolygonId next_id_;
  std::size_t growth_ = 0;
};

}  // namespace edgeland
