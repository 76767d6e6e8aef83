// An edit (spatial/README.md, "An edit"): one relabel overlay per touched cell, splits and
// merges as a draft, then ids (unchanged polygons keep theirs, matched against the old cells
// each new cell covers) and the change set, all building the next state; Landscape::apply
// (landscape.cpp) commits it.
#include "edit.hpp"

#include <algorithm>
#include <limits>

#include "canonical_cell.hpp"
#include "cell_split.hpp"
#include "changes.hpp"
#include "check.hpp"
#include "ids.hpp"
#include "regions.hpp"
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

EditBuilder::EditBuilder(const LandscapeState& state, std::span<const RelabelStep> steps)
    : s_(state),
      steps_(steps),
      next_id_(state.next_id),
      id_end_(std::numeric_limits<PolygonId>::max()) {}

// Steps 1 and 2-7 of the README: each shape's size against the limits, the new tree, its
// limits, what changed (checked in checked mode), and the next state.
EditResult EditBuilder::build() {
  for (const RelabelStep& step : steps_) require_shape_size(vertices_of(*step.shape));
  return result(new_root());
}

EditResult EditBuilder::build(ShapeCut cut, const Box64& box, std::size_t vertices) {
  require_shape_size(vertices);
  reach_.clear();
  reach_.push_back(Reach{box, true, std::move(cut)});
  cut_given_ = true;
  return result(rebuilt_root());
}

void EditBuilder::require_shape_size(std::size_t vertices) const {
  if (vertices > s_.limits.max_shape_vertices)
    throw LimitExceeded(LimitExceeded::Limit::kShapeVertices, s_.limits.max_shape_vertices,
                        vertices);
}

// Steps 5-7 of the README on the new tree.
EditResult EditBuilder::result(NodePtr root) {
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

// Steps 2-6: the touched cells found, each shape cut to them (big shapes), overlaid, split and
// merged as a draft, then given ids. The clipper's internal failures become EditFailure.
NodePtr EditBuilder::new_root() {
  reach_.clear();
  bool any = false;
  for (const RelabelStep& step : steps_) {
    const PolygonSet& shape = step.shape->polygons();
    const Box64 box = bounding_box(shape).value_or(Box64{});
    reach_.push_back(Reach{box, !shape.empty() && s_.world.overlaps_open(box), std::nullopt});
    any = any || reach_.back().in_world;
  }
  if (!any) return s_.root;
  try {
    // With regions, each region cuts the shapes to its own cells (rebuild_region).
    if (!regions_on(s_.config)) cut_shapes(s_.root);
  } catch (const InternalError& e) {
    throw EditFailure{std::string(e.what()) + "\n  subject = " + e.subject_wkt +
                      "\n  clip = " + e.clip_wkt};
  }
  return rebuilt_root();
}

void EditBuilder::cut_shapes(const NodePtr& node) {
  for (std::size_t k = 0; k < steps_.size(); ++k)
    if (reach_[k].in_world && node->box.overlaps_open(reach_[k].box))
      reach_[k].cut = cut_shape_to_cells(node, *steps_[k].shape, reach_[k].box, clip_options());
}

bool EditBuilder::reaches(const Box64& box) const {
  return std::any_of(reach_.begin(), reach_.end(),
                     [&](const Reach& r) { return r.in_world && box.overlaps_open(r.box); });
}

// Steps 3-6 over the reach set up: overlays, splits and merges, ids. The clipper's internal
// failures become EditFailure.
NodePtr EditBuilder::rebuilt_root() {
  try {
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
  return pieces ? *pieces : *steps_[k].shape;
}

// The steps whose shapes reach the cell, in order, in one overlay (relabel_cell).
EditBuilder::Draft EditBuilder::edit_cell(const NodePtr& cell) {
  if (std::optional<LabeledSet> kept = kept_members(*cell))
    return Draft::cell(cell->box, cell->depth, std::move(*kept));
  cell_steps_.clear();
  for (std::size_t k = 0; k < steps_.size(); ++k)
    if (reach_[k].in_world && cell->box.overlaps_open(reach_[k].box))
      cell_steps_.push_back({&shape_in(k, *cell), steps_[k].table});
  std::optional<LabeledSet> content =
      relabel_cell(cell->content, cell_steps_, cell->box, clip_options()).content;
  if (!content) return Draft::keep(cell);
  Draft edited = Draft::cell(cell->box, cell->depth, std::move(*content));
  grow(cell->vertices, edited.vertices);
  return split_if_needed(std::move(edited));
}

// Landscape::remove takes some of a cell's own members out. The overlay of that carve writes
// the canonical decomposition of what remains; when no two remaining members of one material
// share a boundary segment, that is the remaining members as they are (canonical_cell.hpp), so
// the overlay is spared. Else (pieces of a split hole remain) the overlay re-derives them.
std::optional<LabeledSet> EditBuilder::kept_members(const Node& cell) const {
  if (!cut_given_) return std::nullopt;
  const auto& removed = reach_.front().cut->members;
  const auto it = removed.find(&cell);
  if (it == removed.end()) return std::nullopt;
  std::vector<std::size_t> kept;
  for (std::size_t i = 0, r = 0; i < cell.content.labels.size(); ++i) {
    if (r < it->second.size() && it->second[r] == i)
      ++r;
    else
      kept.push_back(i);
  }
  if (!members_stay_apart(cell, kept)) return std::nullopt;
  LabeledSet out{subset(cell.content.set, kept), {}};
  for (std::size_t i : kept) out.labels.push_back(cell.content.labels[i]);
  return out;
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
  // Never above the region depth: regions stay nodes of their own.
  const bool above_regions = static_cast<int>(old->depth) < s_.config.region_depth;
  if (s_.config.grid_depth >= 0 || inner.vertices > s_.config.merge_below || !all_cells ||
      above_regions)
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
  if (node->is_stub()) return unloaded(node);
  if (is_region(s_.config, node->depth)) return rebuild_region(node);
  return rebuild_loaded(node);
}

EditBuilder::Draft EditBuilder::unloaded(const NodePtr& stub) const {
  if (s_.unloaded != UnloadedRegions::kSkip) require_loaded(*stub);
  return Draft::keep(stub);
}

EditBuilder::Draft EditBuilder::rebuild_region(const NodePtr& region) {
  // A cut handed in whole (build(ShapeCut, ...): Landscape::remove) already keeps to cells.
  if (cut_given_) return rebuild_loaded(region);
  cut_shapes(region);
  Draft draft = rebuild_loaded(region);
  for (Reach& r : reach_) r.cut.reset();
  return draft;
}

EditBuilder::Draft EditBuilder::rebuild_loaded(const NodePtr& node) {
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
  if (s_.config.region_ids && is_region(s_.config, old->depth)) return finish_region(draft, old);
  return finish_node(draft, old);
}

NodePtr EditBuilder::finish_node(Draft& draft, const NodePtr& old) {
  if (old->is_cell() || draft.is_cell()) return finish_within(draft, IdSource(old));
  std::vector<NodePtr> children;
  children.reserve(draft.children.size());
  for (std::size_t i = 0; i < draft.children.size(); ++i)
    children.push_back(finish(draft.children[i], old->children[i]));
  return make_inner(draft.box, draft.depth, children, counter_at(draft.depth));
}

NodePtr EditBuilder::finish_region(Draft& draft, const NodePtr& old) {
  const PolygonId saved = next_id_, saved_end = id_end_;
  next_id_ = old->region_next;
  id_end_ = region_id_end(region_of_id(old->region_next));
  NodePtr node = finish_node(draft, old);
  next_id_ = saved;
  id_end_ = saved_end;
  return node;
}

// The counter a node made at this depth keeps: the region's, at the region depth.
PolygonId EditBuilder::counter_at(std::uint32_t depth) const {
  return s_.config.region_ids && is_region(s_.config, depth) ? next_id_ : 0;
}

// A draft lying within the old cells of `previous`, with its ids.
NodePtr EditBuilder::finish_within(Draft& draft, const IdSource& previous) {
  if (draft.is_cell()) {
    std::vector<PolygonId> ids = match_ids(previous, draft.content, next_id_, id_end_);
    return make_cell(draft.box, draft.depth, std::move(draft.content), std::move(ids),
                     counter_at(draft.depth));
  }
  std::vector<NodePtr> children;
  children.reserve(draft.children.size());
  for (Draft& c : draft.children) children.push_back(finish_within(c, previous));
  return make_inner(draft.box, draft.depth, children, counter_at(draft.depth));
}

}  // namespace edgeland::detail
