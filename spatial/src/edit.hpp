#pragma once
// One edit of the landscape as a rebuild of the touched part of the tree (edit.cpp).
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "edgeland/clip/relabel.hpp"
#include "edgeland/clip/valid_set.hpp"
#include "edgeland/spatial/landscape_state.hpp"
#include "edgeland/spatial/material.hpp"
#include "edgeland/spatial/types.hpp"
#include "ids.hpp"
#include "node.hpp"
#include "shape_cut.hpp"

namespace edgeland::detail {

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

// What an edit builds: the next state (its log not yet appended) and its change set.
struct EditResult {
  LandscapeState next;
  ChangeSet changes;
};

// An internal failure while building an edit (the clipper's InternalError or InvalidOverlay, or
// a broken invariant in checked mode): Landscape::apply turns it into a LandscapeInternalError
// carrying the landscape before the edit and the edit's log line.
struct EditFailure {
  std::string what;
};

// Builds the state after one edit, or one batch of edits, from the current one, never changing
// it: the steps of spatial/README.md "An edit" from finding the cells to the change set. An
// edit is one step (its shape and table); a batch (Landscape::apply_batch) several, applied in
// order in one overlay per touched cell (clip's relabel_cell of several steps). The steps, their
// shapes and tables stay the caller's. Throws LimitExceeded or EditFailure.
class EditBuilder {
 public:
  EditBuilder(const LandscapeState& state, std::span<const RelabelStep> steps);
  EditResult build();
  // An edit of one step whose shape comes already cut to the cells it reaches (the pieces within
  // each cell's box; `box` bounds them all, `vertices` counts them): Landscape::remove. The
  // step's own shape is what the cells the cut does not reach take.
  EditResult build(ShapeCut cut, const Box64& box, std::size_t vertices);

 private:
  // A part of the new tree before it has ids: an old node kept as it is (`kept`), a new cell
  // (`content`), or a new inner node over `children` (split_boxes order). Ids are given only
  // once the new tree's shape is final (finish), so a cell that a split or merge replaces
  // within the edit never takes an id, and every new cell takes its ids from the old cells
  // it covers, not from a cell the edit made and threw away.
  struct Draft {
    NodePtr kept;
    Box64 box;
    std::uint32_t depth = 0;
    LabeledSet content;
    std::vector<Draft> children;
    std::size_t vertices = 0;
    static Draft keep(const NodePtr& node);
    static Draft cell(const Box64& box, std::uint32_t depth, LabeledSet content);
    static Draft inner(const Box64& box, std::uint32_t depth, std::vector<Draft> children);
    bool is_cell() const { return kept ? kept->is_cell() : children.empty(); }
    const LabeledSet& cell_content() const { return kept ? kept->content : content; }
  };
  // The shape of one step of the edit being built, and what of it each cell takes.
  struct Reach {
    Box64 box;
    bool in_world = false;        // the shape meets the world's interior
    std::optional<ShapeCut> cut;  // the shape cut to the touched cells (big shapes only)
  };

  NodePtr new_root();
  // Whether some step's shape box meets the box's interior (the nodes an edit descends to).
  bool reaches(const Box64& box) const;
  // Each step's shape cut to the cells below `node` (cut_shape_to_cells; big shapes only).
  void cut_shapes(const NodePtr& node);
  NodePtr rebuilt_root();
  EditResult result(NodePtr root);
  void require_shape_size(std::size_t vertices) const;
  Draft rebuild(const NodePtr& node);
  Draft rebuild_loaded(const NodePtr& node);
  // A region (LandscapeConfig::region_depth): the shape cut to its cells alone, so its result
  // depends on nothing outside it. An unloaded one is refused or kept, as the policy says.
  Draft rebuild_region(const NodePtr& region);
  Draft unloaded(const NodePtr& stub) const;
  Draft edit_cell(const NodePtr& cell);
  // A cell of Landscape::remove whose other members stay apart: those members as they are.
  std::optional<LabeledSet> kept_members(const Node& cell) const;
  // What of step k's shape a cell's overlay takes: its pieces when the shape was cut to the
  // cells (shape_cut.hpp), else the whole shape.
  const ValidSet& shape_in(std::size_t k, const Node& cell) const;
  Draft split_if_needed(Draft cell);
  Draft merge_if_small(const NodePtr& old, std::vector<Draft> children);
  NodePtr finish(Draft& draft, const NodePtr& old);
  NodePtr finish_node(Draft& draft, const NodePtr& old);
  NodePtr finish_within(Draft& draft, const IdSource& previous);
  // A region with its own ids takes fresh ones from its counter, which its node keeps.
  NodePtr finish_region(Draft& draft, const NodePtr& old);
  PolygonId counter_at(std::uint32_t depth) const;
  LandscapeState next_state(NodePtr root, const ChangeSet& changes) const;
  ClipOptions clip_options() const { return ClipOptions{.checked = s_.checked}; }
  // Counts the vertices a new cell adds over what it replaces (and the cells a split adds), and
  // throws LimitExceeded as soon as the landscape could pass its vertex (cell) limit: a runaway
  // split stops early.
  void grow(std::size_t before, std::size_t after);
  void grow_cells(std::size_t added);

  const LandscapeState& s_;
  std::span<const RelabelStep> steps_;
  std::vector<Reach> reach_;             // per step
  bool cut_given_ = false;               // build(ShapeCut, ...): the cut came in whole
  std::vector<RelabelStep> cell_steps_;  // the steps reaching the cell being overlaid
  PolygonId next_id_;
  PolygonId id_end_;  // the end of the id space next_id_ counts in
  std::size_t growth_ = 0;
  std::size_t cell_growth_ = 0;
};

}  // namespace edgeland::detail
