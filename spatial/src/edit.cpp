// An edit (spatial/README.md, "An edit"): one relabel overlay per touched cell, splits and
// merges as a draft, then ids (unchanged polygons keep theirs, matched against the old cells
// each new cell covers) and the change set; the landscape changes only at the commit at the
// very end.
#include "edit.hpp"

#include <algorithm>

#include "cell_overlay.hpp"
#include "cell_split.hpp"
#include "changes.hpp"
#include "check.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "edit_log.hpp"
#include "ids.hpp"
#include "landscape_access.hpp"
#include "shape_cut.hpp"

namespace edgeland {
namespace {

using detail::NodePtr;

// Interiors of two closed boxes meet.
bool open_overlap(const Box64& a, const Box64& b) {
  return a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y;
}

std::size_t vertices_of(const LabeledSet& s) {
  std::size_t n = 0;
  for (const Polygon& p : s.set.polygons()) n += p.size();
  return n;
}

}  // namespace

LandscapeEditor::LandscapeEditor(const Landscape& l, const ValidSet& shape, EditTable table)
    : l_(l),
      s_(LandscapeAccess::state(l)),
      shape_(shape),
      table_(std::move(table)),
      next_id_(s_.next_id) {
  if (const auto b = bounding_box(shape.polygons())) shape_box_ = *b;
}

void LandscapeEditor::grow(std::size_t before, std::size_t after) {
  if (after <= before) return;
  growth_ += after - before;
  const std::size_t could_be = s_.root->vertices + growth_;
  if (could_be > s_.limits.max_vertices)
    throw LimitExceeded(LimitExceeded::Limit::kVertices, s_.limits.max_vertices, could_be);
}

void LandscapeEditor::grow_cells(std::size_t added) {
  cell_growth_ += added;
  const std::size_t could_be = s_.root->cells + cell_growth_;
  if (could_be > s_.limits.max_cells)
    throw LimitExceeded(LimitExceeded::Limit::kCells, s_.limits.max_cells, could_be);
}

LandscapeEditor::Draft LandscapeEditor::Draft::keep(const NodePtr& node) {
  Draft d;
  d.kept = node;
  d.vertices = node->vertices;
  return d;
}

LandscapeEditor::Draft LandscapeEditor::Draft::cell(const Box64& box, std::uint32_t depth,
                                                    LabeledSet content) {
  Draft d;
  d.box = box;
  d.depth = depth;
  d.vertices = vertices_of(content);
  d.content = std::move(content);
  return d;
}

LandscapeEditor::Draft LandscapeEditor::Draft::inner(const Box64& box, std::uint32_t depth,
                                                     std::vector<Draft> children) {
  Draft d;
  d.box = box;
  d.depth = depth;
  for (const Draft& c : children) d.vertices += c.vertices;
  d.children = std::move(children);
  return d;
}

const ValidSet& LandscapeEditor::shape_in(const detail::Node& cell) const {
  const ValidSet* pieces = cut_ ? cut_->of(cell) : nullptr;
  return pieces ? *pieces : shape_;
}

LandscapeEditor::Draft LandscapeEditor::edit_cell(const NodePtr& cell) {
  std::optional<LabeledSet> content =
      detail::overlay_cell(*cell, shape_in(*cell), table_.table, clip_options());
  if (!content) return Draft::keep(cell);
  Draft edited = Draft::cell(cell->box, cell->depth, std::move(*content));
  grow(cell->vertices, edited.vertices);
  return split_if_needed(std::move(edited));
}

LandscapeEditor::Draft LandscapeEditor::split_if_needed(Draft cell) {
  const LandscapeConfig& config = s_.config;
  if (config.grid_depth >= 0 || cell.vertices <= config.edge_cap ||
      !detail::can_split(cell.box, config))
    return cell;
  const std::vector<Box64> boxes = detail::split_boxes(cell.box, config);
  grow_cells(boxes.size() - 1);
  std::vector<LabeledSet> parts =
      cut_to_windows(cell.content.set, cell.content.labels, boxes, clip_options());
  std::vector<Draft> children;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    children.push_back(Draft::cell(boxes[i], cell.depth + 1, std::move(parts[i])));
  std::size_t children_vertices = 0;
  for (const Draft& child : children) children_vertices += child.vertices;
  grow(cell.vertices, children_vertices);
  for (Draft& child : children) child = split_if_needed(std::move(child));
  return Draft::inner(cell.box, cell.depth, std::move(children));
}

LandscapeEditor::Draft LandscapeEditor::merge_if_small(const NodePtr& old,
                                                       std::vector<Draft> children) {
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

LandscapeEditor::Draft LandscapeEditor::rebuild(const NodePtr& node) {
  if (!open_overlap(node->box, shape_box_)) return Draft::keep(node);
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
NodePtr LandscapeEditor::finish(Draft& draft, const NodePtr& old) {
  if (draft.kept) return draft.kept;
  if (old->is_cell() || draft.is_cell()) return finish_within(draft, detail::IdSource(old));
  std::vector<NodePtr> children;
  for (std::size_t i = 0; i < draft.children.size(); ++i)
    children.push_back(finish(draft.children[i], old->children[i]));
  return detail::make_inner(draft.box, draft.depth, children);
}

// A draft lying within the old cells of `previous`, with its ids.
NodePtr LandscapeEditor::finish_within(Draft& draft, const detail::IdSource& previous) {
  if (draft.is_cell()) {
    std::vector<PolygonId> ids = detail::match_ids(previous, draft.content, next_id_);
    return detail::make_cell(draft.box, draft.depth, std::move(draft.content), std::move(ids));
  }
  std::vector<NodePtr> children;
  for (Draft& c : draft.children) children.push_back(finish_within(c, previous));
  return detail::make_inner(draft.box, draft.depth, children);
}

ChangeSet LandscapeEditor::run(Landscape& target, const std::function<std::string()>& log_line) {
  const std::size_t shape_vertices = [&] {
    std::size_t n = 0;
    for (const Polygon& p : shape_.polygons()) n += p.size();
    return n;
  }();
  if (shape_vertices > s_.limits.max_shape_vertices)
    throw LimitExceeded(LimitExceeded::Limit::kShapeVertices, s_.limits.max_shape_vertices,
                        shape_vertices);
  NodePtr root = s_.root;
  try {
    if (!shape_.polygons().empty() && open_overlap(s_.world, shape_box_)) {
      cut_ = detail::cut_shape_to_cells(s_.root, shape_, shape_box_, clip_options());
      Draft draft = rebuild(s_.root);
      root = finish(draft, s_.root);
    }
  } catch (const InternalError& e) {
    throw detail::internal_error(
        l_, std::string(e.what()) + "\n  subject = " + e.subject_wkt + "\n  clip = " + e.clip_wkt,
        log_line());
  } catch (const InvalidOverlay& e) {
    throw detail::internal_error(l_, e.what(), log_line());
  }
  if (root->vertices > s_.limits.max_vertices)
    throw LimitExceeded(LimitExceeded::Limit::kVertices, s_.limits.max_vertices, root->vertices);
  if (root->cells > s_.limits.max_cells)
    throw LimitExceeded(LimitExceeded::Limit::kCells, s_.limits.max_cells, root->cells);
  detail::Changes changes = detail::diff(s_.root, root);
  if (s_.checked) {
    const std::string problem = detail::check_edit(l_, root, changes, s_.next_id);
    if (!problem.empty()) throw detail::internal_error(l_, problem, log_line());
  }
  ChangeSet out = detail::change_set(changes);
  // The next state, committed by one assignment: nothing before it touches `target`.
  detail::LandscapeState next = s_;
  auto areas = std::make_shared<detail::AreaTable>(*s_.areas);
  for (const auto& [m, delta] : out.twice_area_delta)
    if (m != kEmpty) (*areas)[m.value()] += delta;
  next.root = std::move(root);
  next.areas = std::move(areas);
  next.next_id = next_id_;
  ++next.edits;
  if (next.logging) detail::append_log(next, log_line());
  LandscapeAccess::commit(target, std::move(next));
  return out;
}

}  // namespace edgeland
