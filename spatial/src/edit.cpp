// An edit (spatial/README.md, "An edit"): one relabel overlay per touched cell, ids kept for
// unchanged polygons, splits and merges, then the change set; the landscape changes only at
// the commit at the very end.
#include "edit.hpp"

#include <algorithm>

#include "cell_split.hpp"
#include "changes.hpp"
#include "check.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "ids.hpp"
#include "log_line.hpp"

namespace edgeland {
namespace {

using detail::NodePtr;

// Interiors of two closed boxes meet.
bool open_overlap(const Box64& a, const Box64& b) {
  return a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y;
}

bool same_content(const LabeledSet& a, const LabeledSet& b) {
  return a.labels == b.labels && a.set.polygons() == b.set.polygons();
}

}  // namespace

LandscapeEditor::LandscapeEditor(const Landscape& l, const ValidSet& shape, EditTable table)
    : l_(l), shape_(shape), table_(table), next_id_(l.next_id_) {
  if (const auto b = bounding_box(shape.polygons())) shape_box_ = *b;
}

NodePtr LandscapeEditor::cell_from(const Box64& box, std::uint32_t depth, LabeledSet content,
                                   const detail::IdSource& previous) {
  std::vector<PolygonId> ids = detail::match_ids(previous, content, next_id_);
  return detail::make_cell(box, depth, std::move(content), std::move(ids));
}

void LandscapeEditor::grow(std::size_t before, std::size_t after) {
  if (after <= before) return;
  growth_ += after - before;
  const std::size_t could_be = l_.root_->vertices + growth_;
  if (could_be > l_.limits_.max_vertices)
    throw LimitExceeded(LimitExceeded::Limit::kVertices, l_.limits_.max_vertices, could_be);
}

namespace {

std::size_t vertices_of(const LabeledSet& s) {
  std::size_t n = 0;
  for (const Polygon& p : s.set.polygons()) n += p.size();
  return n;
}

}  // namespace

NodePtr LandscapeEditor::edit_cell(const NodePtr& cell) {
  LabeledClipResult r = relabel(cell->content.set, cell->content.labels, shape_, cell->box,
                                table_.table, clip_options());
  if (same_content(r.regions, cell->content)) return cell;
  grow(cell->vertices, vertices_of(r.regions));
  return split_if_needed(cell_from(cell->box, cell->depth, std::move(r.regions),
                                   detail::IdSource::of(*cell)));
}

NodePtr LandscapeEditor::split_if_needed(const NodePtr& cell) {
  const LandscapeConfig& config = l_.config_;
  if (config.grid_depth >= 0 || cell->vertices <= config.edge_cap || !detail::can_split(cell->box, config))
    return cell;
  const std::vector<Box64> boxes = detail::split_boxes(cell->box, config);
  std::vector<LabeledSet> parts =
      cut_to_windows(cell->content.set, cell->content.labels, boxes, clip_options());
  std::size_t children_vertices = 0;
  for (const LabeledSet& part : parts) children_vertices += vertices_of(part);
  grow(cell->vertices, children_vertices);
  const detail::IdSource previous = detail::IdSource::of(*cell);
  std::vector<NodePtr> children;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    children.push_back(split_if_needed(cell_from(boxes[i], cell->depth + 1, std::move(parts[i]), previous)));
  return detail::make_inner(cell->box, cell->depth, children);
}

NodePtr LandscapeEditor::merge_if_small(const NodePtr& inner) {
  const LandscapeConfig& config = l_.config_;
  if (config.grid_depth >= 0 || inner->vertices > config.merge_below) return inner;
  PolygonSet all;
  std::vector<RegionLabel> labels;
  detail::IdSource previous;
  for (std::uint32_t i = 0; i < inner->child_count; ++i) {
    const NodePtr& c = inner->children[i];
    if (!c->is_cell()) return inner;
    all.insert(all.end(), c->polygon_set().begin(), c->polygon_set().end());
    labels.insert(labels.end(), c->content.labels.begin(), c->content.labels.end());
    previous.add(*c);
  }
  // The children lie in boxes with disjoint interiors: together a valid set (validated again
  // here: merges are rare and small), re-united without any crossing, so without rounding.
  LabeledClipResult merged =
      relabel(ValidSet(std::move(all)), labels, ValidSet(), inner->box, {}, clip_options());
  return cell_from(inner->box, inner->depth, std::move(merged.regions), previous);
}

NodePtr LandscapeEditor::rebuild(const NodePtr& node) {
  if (!open_overlap(node->box, shape_box_)) return node;
  if (node->is_cell()) return edit_cell(node);
  std::vector<NodePtr> children(node->child_count);
  bool changed = false;
  for (std::uint32_t i = 0; i < node->child_count; ++i) {
    children[i] = rebuild(node->children[i]);
    changed = changed || children[i] != node->children[i];
  }
  if (!changed) return node;
  return merge_if_small(detail::make_inner(node->box, node->depth, children));
}

ChangeSet LandscapeEditor::run(Landscape& target, const std::function<std::string()>& log_line) {
  const std::size_t shape_vertices = [&] {
    std::size_t n = 0;
    for (const Polygon& p : shape_.polygons()) n += p.size();
    return n;
  }();
  if (shape_vertices > l_.limits_.max_shape_vertices)
    throw LimitExceeded(LimitExceeded::Limit::kShapeVertices, l_.limits_.max_shape_vertices,
                        shape_vertices);
  NodePtr root = l_.root_;
  try {
    if (!shape_.polygons().empty() && open_overlap(l_.world_, shape_box_)) root = rebuild(l_.root_);
  } catch (const InternalError& e) {
    throw detail::internal_error(l_, std::string(e.what()) + "\n  subject = " + e.subject_wkt +
                                         "\n  clip = " + e.clip_wkt, log_line());
  } catch (const InvalidOverlay& e) {
    throw detail::internal_error(l_, e.what(), log_line());
  }
  if (root->vertices > l_.limits_.max_vertices)
    throw LimitExceeded(LimitExceeded::Limit::kVertices, l_.limits_.max_vertices, root->vertices);
  detail::Changes changes = detail::diff(l_.root_, root);
  if (l_.checked_) {
    const std::string problem = detail::check_edit(l_, root, changes, l_.next_id_);
    if (!problem.empty()) throw detail::internal_error(l_, problem, log_line());
  }
  ChangeSet out = detail::change_set(changes);
  // Commit: nothing above may have touched `target`.
  auto areas = std::make_shared<Landscape::AreaTable>(*l_.areas_);
  for (const auto& [m, delta] : out.twice_area_delta)
    if (m != kEmpty) (*areas)[m] += delta;
  target.root_ = std::move(root);
  target.areas_ = std::move(areas);
  target.next_id_ = next_id_;
  ++target.edits_;
  if (target.logging_) detail::append_log(target, log_line());
  return out;
}

}  // namespace edgeland
