// An edit (spatial/README.md, "An edit"): one relabel overlay per touched cell, splits and
// merges as a draft, then ids (unchanged polygons keep theirs, matched against the old cells
// each new cell covers) and the change set, all building the next state; Landscape::apply
// (landscape.cpp) commits it.
#include "edit.hpp"

#include <algorithm>

#include "cell_split.hpp"
#include "changes.hpp"
#include "check.hpp"
#include "ids.hpp"
#include "shape_cut.hpp"
#include "split_content.hpp"

namespace edgeland::detail {
namespace {

std::size_t vertices_of(const LabeledSet& s) {
  std::size_t n = 0;
  for (const Polygon& p : s.set.polygons()) n += p.size();
  return n;
}

std::size_t vertices_of(const ValidSet& s) {
  std::size_t n = 0;
  for (const Polygon& p : s.polygons()) n += p.size();
  return n;
}

}  // namespace

EditBuilder::EditBuilder(const LandscapeState& state, std::span<const EditStep> steps)
    : s_(state), steps_(steps), next_id_(state.next_id) {}

// Steps 1 and 2-7 of the README: each shape's size against the limits, the new tree, its limits,
// what changed (checked in checked mode), and the next state.
EditResult EditBuilder::build() {
  for (const EditStep& step : steps_) {
    const std::size_t shape_vertices = vertices_of(*step.shape);
    if (shape_vertices > s_.limits.max_shape_vertices)
      throw LimitExceeded(LimitExceeded::Limit::kShapeVertices, s_.limits.max_shape_vertices,
                          shape_vertices);
  }
  NodePtr root = new_root();
  if (root->vertices > s_.limits.max_vertices)
    throw LimitExceeded(LimitExceeded::Limit::kVertices, s_.limits.max_vertices, root->vertices);
  if (root->cells > s_.limits.max_cells)
    throw LimitExceeded(LimitExceeded::Limit::kCells, s_.limits.max_cells, root->cells);
  const Changes changes = diff(s_.root, root);
  if (s_.checked) {
    const std::string problem = check_edit(s_, root, changes, s_.next_id);
    if (!problem.empty()) throw EditFailure{problem};
  }
  ChangeSet out = change_set(changes);
  return {next_state(std::move(root), out), std::move(out)};
}

// Steps 2-6: the touched cells found, each big shape cut to them, overlaid, split and merged as a
// draft, then given ids. The clipper's internal failures become EditFailure.
NodePtr EditBuilder::new_root() {
  reach_.clear();
  bool any = false;
  for (const EditStep& step : steps_) {
    const ValidSet& shape = *step.shape;
    Reach& r = reach_.emplace_back();
    r.shape = &shape;
    r.box = bounding_box(shape.polygons()).value_or(Box64{});
    r.in_world = !shape.polygons().empty() && s_.world.overlaps_open(r.box);
    any = any || r.in_world;
  }
  if (!any) return s_.root;
  try {
    for (Reach& r : reach_)
      if (r.in_world) r.cut = cut_shape_to_cells(s_.root, *r.shape, r.box, clip_options());
    Draft draft = rebuild(s_.root);
    return finish(draft, s_.root);
  } catch (const InternalError& e) {
    throw EditFailure{std::string(e.what()) + "\n  subject = " + e.subject_wkt +
                      "\n  clip = " + e.clip_wkt};
  } catch (const InvalidOverlay& e) {
    throw EditFailure{e.what()};
  }
}

// Step 7's state: the new tree, the areas moved by the change set, the ids handed out, one more
// edit (the log line is Landscape::apply's to append).
LandscapeState EditBuilder::next_state(NodePtr root, const ChangeSet& changes) const {
  LandscapeState next = s_;
  auto areas = std::make_shared<AreaTable>(*s_.areas);
  for (const auto& [m, delta] : changes.twice_area_delta)
    if (m != kEmpty) (*areas)[m.value()] += delta;
  next.root = std::move(root);
  next.areas = std::move(areas);
  next.next_id = next_id_;
  ++next.edits;
  return next;
}

void EditBuilder::grow(std::size_t before, std::size_t after) {
  if (after <= before) return;
  growth_ += after - before;
  const std::size_t could_be = s_.root->vertices + growth_;
  if (could_be > s_.limits.max_vertices)
    throw LimitExceeded(LimitExceeded::Limit::kVertices, s_.limits.max_vertices, could_be);
}

void EditBuilder::grow_cells(std::size_t added) {
  cell_growth_ += added;
  const std::size_t could_be = s_.root->cells + cell_growth_;
  if (could_be > s_.limits.max_cells)
    throw LimitExceeded(LimitExceeded::Limit::kCells, s_.limits.max_cells, could_be);
}

EditBuilder::Draft EditBuilder::Draft::keep(const NodePtr& node) {
  Draft d;
  d.kept = node;
  d.vertices = node->vertices;
  return d;
}

EditBuilder::Draft EditBuilder::Draft::cell(const Box64& box, std::uint32_t depth,
                                            LabeledSet content) {
  Draft d;
  d.box = box;
  d.depth = depth;
  d.vertices = vertices_of(content);
  d.content = std::move(content);
  return d;
}

EditBuilder::Draft EditBuilder::Draft::inner(const Box64& box, std::uint32_t depth,
                                             std::vector<Draft> children) {
  Draft d;
  d.box = box;
  d.depth = depth;
  for (const Draft& c : children) d.vertices += c.vertices;
  d.children = std::move(children);
  return d;
}

const ValidSet& EditBuilder::shape_in(std::size_t k, const Node& cell) const {
  const ValidSet* pieces = reach_[k].cut ? reach_[k].cut->of(cell) : nullptr;
  return pieces ? *pieces : *reach_[k].shape;
}

bool EditBuilder::reaches(const Box64& box) const {
  for (const Reach& r : reach_)
    if (r.in_world && box.overlaps_open(r.box)) return true;
  return false;
}

EditBuilder::Draft EditBuilder::edit_cell(const NodePtr& cell) {
  cell_steps_.clear();
  for (std::size_t k = 0; k < steps_.size(); ++k)
    if (reach_[k].in_world && cell->box.overlaps_open(reach_[k].box))
      cell_steps_.push_back({&shape_in(k, *cell), steps_[k].table.table});
  std::optional<LabeledSet> content =
      relabel_cell(cell->content, cell_steps_, cell->box, clip_options()).content;
  if (!content) return Draft::keep(cell);
  Draft edited = Draft::cell(cell->box, cell->depth, std::move(*content));
  grow(cell->vertices, edited.vertices);
  return split_if_needed(std::move(edited));
}

EditBuilder::Draft EditBuilder::split_if_needed(Draft cell) {
  const LandscapeConfig& config = s_.config;
  if (config.grid_depth >= 0 || cell.vertices <= config.edge_cap || !can_split(cell.box, config))
    return cell;
  const std::vector<Box64> boxes = split_boxes(cell.box, config);
  grow_cells(boxes.size() - 1);
  std::vector<LabeledSet> parts = cut_to_children(std::move(cell.content), boxes, clip_options());
  std::vector<Draft> children;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    children.push_back(Draft::cell(boxes[i], cell.depth + 1, std::move(parts[i])));
  std::size_t children_vertices = 0;
  for (const Draft& child : children) children_vertices += child.vertices;
  grow(cell.vertices, children_vertices);
  for (Draft& child : children) child = split_if_needed(std::move(child));
  return Draft::inner(cell.box, cell.depth, std::move(children));
}

EditBuilder::Draft EditBuilder::merge_if_small(const NodePtr& old, std::vector<Draft> children) {
  Draft inner = Draft::inner(old->box, old->depth, std::move(children));
  const bool all_cells = std::all_of(inner.children.begin(), inner.children.end(),
                                     [](const Draft& c) { return c.is_cell(); });
  if (s_.config.grid_depth >= 0 || inner.vertices > s_.config.merge_below || !all_cells)
    return inner;
  PolygonSet all;
  std::vector<RegionLabel> labels;
  for (const Draft& c : inner.children) {
    const LabeledSet& content = c.cell_content();
    all.insert(all.end(), content.set.polygons().begin(), content.set.polygons().end());
    labels.insert(labels.end(), content.labels.begin(), content.labels.end());
  }
  // The children lie in boxes with disjoint interiors: together a valid set (validated again
  // here: merges are rare and small), re-united without any crossing, so without rounding.
  LabeledClipResult merged =
      relabel(ValidSet(std::move(all)), labels, ValidSet(), old->box, {}, clip_options());
  return Draft::cell(old->box, old->depth, std::move(merged.regions));
}

EditBuilder::Draft EditBuilder::rebuild(const NodePtr& node) {
  if (!reaches(node->box)) return Draft::keep(node);
  if (node->is_cell()) return edit_cell(node);
  std::vector<Draft> children(node->child_count);
  bool changed = false;
  for (std::uint32_t i = 0; i < node->child_count; ++i) {
    children[i] = rebuild(node->children[i]);
    changed = changed || children[i].kept != node->children[i];
  }
  if (!changed) return Draft::keep(node);
  return merge_if_small(node, std::move(children));
}

// Stage "Ids": a new cell takes ids from the old cells its box covers (the old node in its
// place, or the old cell it was split from). An unchanged polygon lies in one of those, so it
// keeps its id however the cells around it split or merged. Fresh ids go out in tree order.
NodePtr EditBuilder::finish(Draft& draft, const NodePtr& old) {
  if (draft.kept) return draft.kept;
  if (old->is_cell() || draft.is_cell()) return finish_within(draft, IdSource(old));
  std::vector<NodePtr> children;
  for (std::size_t i = 0; i < draft.children.size(); ++i)
    children.push_back(finish(draft.children[i], old->children[i]));
  return make_inner(draft.box, draft.depth, children);
}

// A draft lying within the old cells of `previous`, with its ids.
NodePtr EditBuilder::finish_within(Draft& draft, const IdSource& previous) {
  if (draft.is_cell()) {
    std::vector<PolygonId> ids = match_ids(previous, draft.content, next_id_);
    return make_cell(draft.box, draft.depth, std::move(draft.content), std::move(ids));
  }
  std::vector<NodePtr> children;
  for (Draft& c : draft.children) children.push_back(finish_within(c, previous));
  return make_inner(draft.box, draft.depth, children);
}

}  // namespace edgeland::detail
