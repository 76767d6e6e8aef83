#include "check.hpp"

#include <algorithm>
#include <set>
#include <sstream>

#include "canonical_cell.hpp"
#include "cell_split.hpp"
#include "edgeland/kernel/area.hpp"
#include "edit_log.hpp"
#include "regions.hpp"
#include "save_load.hpp"

namespace edgeland::detail {
namespace {

std::string name(const Node& n) {
  std::ostringstream s;
  s << (n.is_cell() ? "cell (" : "node (") << n.box.min.x << ' ' << n.box.min.y << ' '
    << n.box.max.x << ' ' << n.box.max.y << ")";
  return s.str();
}

void check_parallel_arrays(const Node& c, std::vector<std::string>& problems) {
  const std::size_t n = c.polygon_set().size();
  if (c.content.labels.size() != n || c.ids.size() != n || c.boxes.size() != n)
    problems.push_back(name(c) + ": labels, ids or boxes do not match the polygons");
}

// I1 and the stored boxes.
void check_validity(const Node& c, std::vector<std::string>& problems) {
  const PolygonSet& polys = c.polygon_set();
  const ValidationReport v = validate(polys, 1);
  if (!v.ok()) problems.push_back(name(c) + ": invalid: " + v.violations.front().describe());
  for (std::size_t i = 0; i < polys.size(); ++i) {
    const auto b = bounding_box(polys[i]);
    // `b` is empty only for an empty ring, which no ValidSet holds (not reached by tests).
    if (b && *b != c.boxes[i])
      problems.push_back(name(c) + ": polygon " + std::to_string(i) + " has a wrong box");
  }
}

// I2 and the materials.
void check_placement(const Node& c, std::vector<std::string>& problems) {
  for (std::size_t i = 0; i < c.polygons; ++i) {
    if (!c.box.contains(c.boxes[i]))
      problems.push_back(name(c) + ": polygon " + std::to_string(i) + " outside the cell");
    if (c.content.labels[i] == 0 || c.content.labels[i] >= kMaterialCount)
      problems.push_back(name(c) + ": polygon " + std::to_string(i) + " has material " +
                         std::to_string(c.content.labels[i]));
  }
}

// I5, and the grid's shape: in grid mode every cell that can split lies at the grid depth.
void check_shape(const Node& c, const LandscapeConfig& config, std::vector<std::string>& problems) {
  const bool grid = config.grid_depth >= 0;
  if (!grid && c.vertices > config.edge_cap && can_split(c.box, config))
    problems.push_back(name(c) + ": " + std::to_string(c.vertices) + " edges, over the cap");
  if (grid && static_cast<int>(c.depth) < config.grid_depth && can_split(c.box, config))
    problems.push_back(name(c) + ": a grid cell above the grid depth " +
                       std::to_string(config.grid_depth));
  if (static_cast<int>(c.depth) < config.region_depth)
    problems.push_back(name(c) + ": a cell above the region depth " +
                       std::to_string(config.region_depth));
}

// A node keeps an id counter exactly when it is a region with its own ids.
void check_counter_place(const Node& n, const LandscapeConfig& config,
                         std::vector<std::string>& problems) {
  const bool keeps = config.region_ids && is_region(config, n.depth);
  if (keeps != (n.region_next != 0))
    problems.push_back(name(n) + (keeps ? ": a region without its id counter"
                                        : ": an id counter on a node that is no region"));
}

void check_sums(const Node& n, const NodePtr& rebuilt, std::vector<std::string>& problems) {
  if (rebuilt->polygons != n.polygons || rebuilt->vertices != n.vertices ||
      rebuilt->cells != n.cells || rebuilt->deepest != n.deepest || rebuilt->hash != n.hash ||
      rebuilt->cut_x != n.cut_x || rebuilt->cut_y != n.cut_y || rebuilt->x_line != n.x_line ||
      rebuilt->y_line != n.y_line)
    problems.push_back(name(n) + ": stored sums or hash differ from its content");
}

}  // namespace

void check_cell_content(const Node& c, const LandscapeConfig& config,
                        std::vector<std::string>& problems) {
  const std::size_t before = problems.size();
  check_placement(c, problems);
  if (problems.size() != before) return;
  check_shape(c, config, problems);
  check_counter_place(c, config, problems);
  if (!cell_is_canonical(c))
    problems.push_back(name(c) + ": content is not the canonical decomposition of its regions");
}

void check_cell(const Node& c, const LandscapeConfig& config, std::vector<std::string>& problems) {
  const std::size_t before = problems.size();
  check_parallel_arrays(c, problems);
  if (problems.size() != before) return;
  check_validity(c, problems);
  if (problems.size() != before) return;
  check_cell_content(c, config, problems);
  check_sums(c, make_cell(c.box, c.depth, c.content, c.ids, c.region_next), problems);
}

void check_inner(const Node& n, const LandscapeConfig& config, std::vector<std::string>& problems) {
  if (!can_split(n.box, config)) {
    problems.push_back(name(n) + ": split although it may not");
    return;
  }
  const std::vector<Box64> boxes = split_boxes(n.box, config);
  if (boxes.size() != n.child_count) {
    problems.push_back(name(n) + ": wrong number of children");
    return;
  }
  std::vector<NodePtr> children;
  bool all_cells = true;
  for (std::uint32_t i = 0; i < n.child_count; ++i) {
    const NodePtr& c = n.children[i];
    if (!c || c->box != boxes[i] || c->depth != n.depth + 1)
      problems.push_back(name(n) + ": child " + std::to_string(i) + " is not its part of the box");
    if (!c) return;
    all_cells = all_cells && c->is_cell();
    children.push_back(c);
  }
  const bool may_merge = config.grid_depth < 0 && static_cast<int>(n.depth) >= config.region_depth;
  if (may_merge && all_cells && n.vertices <= config.merge_below)
    problems.push_back(name(n) + ": children small enough to merge");
  check_counter_place(n, config, problems);
  if (config.grid_depth >= 0 && static_cast<int>(n.depth) >= config.grid_depth)
    problems.push_back(name(n) + ": grid node below the grid depth");
  check_sums(n, make_inner(n.box, n.depth, children, n.region_next), problems);
}

std::string check_edit(const LandscapeState& before, const NodePtr& new_root,
                       const Changes& changes, PolygonId old_next_id) {
  std::vector<std::string> problems;
  const LandscapeConfig& config = before.config;
  if (new_root->box != before.world || new_root->depth != 0)
    problems.push_back("the root is not the world");
  for (const NodePtr& c : changes.new_cells) check_cell(*c, config, problems);
  for (const NodePtr& n : changes.new_inner) check_inner(*n, config, problems);
  std::set<PolygonId> old_ids, new_ids;
  for (const NodePtr& c : changes.old_cells) old_ids.insert(c->ids.begin(), c->ids.end());
  for (const NodePtr& c : changes.new_cells) {
    // With ids per region, "old" ids are those below the region's counter before the edit.
    PolygonId old_next = old_next_id;
    if (config.region_ids) {
      const RegionHere now = region_above(new_root, config, c->box.min);
      check_region_ids(c->ids, now.index, now.node->region_next, name(*c), problems);
      old_next = region_above(before.root, config, c->box.min).node->region_next;
    }
    for (PolygonId id : c->ids) {
      if (!new_ids.insert(id).second) problems.push_back("id " + std::to_string(id) + " twice");
      if (id < old_next && !old_ids.count(id))
        problems.push_back("id " + std::to_string(id) + " taken from a polygon that stays");
    }
  }
  // gcov ascribes the unwinding of the strings built below, run only when building one throws
  // (out of memory), to these lines: not reached by tests.
  return problems.empty()
             ? std::string()
             : problems.front() + (problems.size() > 1
                                       ? " (and " + std::to_string(problems.size() - 1) + " more)"
                                       : "");
}

namespace {

// The region a walk of the tree is in (region_ids): its index and counter.
struct WalkRegion {
  std::uint64_t index = 0;
  PolygonId counter = 0;
};

void check_subtree(const NodePtr& n, const LandscapeConfig& config,
                   std::vector<std::string>& problems, std::set<PolygonId>& ids,
                   detail::AreaTable& areas, std::uint64_t index, WalkRegion region) {
  if (config.region_ids && is_region(config, n->depth)) {
    check_region_counter(*n, index, name(*n), problems);
    region = {index, n->region_next};
  }
  if (n->is_stub()) {
    // Its content is elsewhere: its summary counts, its place was checked by its parent.
    for (const auto& [m, a] : n->stub->twice_areas) areas[m.value()] += a;
    return;
  }
  if (n->is_cell()) {
    check_cell(*n, config, problems);
    if (config.region_ids)
      check_region_ids(n->ids, region.index, region.counter, name(*n), problems);
    for (std::size_t i = 0; i < n->ids.size(); ++i) {
      if (!ids.insert(n->ids[i]).second)
        problems.push_back("id " + std::to_string(n->ids[i]) + " twice");
      if (i < n->content.labels.size() && n->content.labels[i] < kMaterialCount)
        areas[n->content.labels[i]] += twice_signed_area(n->polygon_set()[i]);
    }
    return;
  }
  check_inner(*n, config, problems);
  for (std::uint32_t i = 0; i < n->child_count; ++i)
    if (n->children[i])
      check_subtree(n->children[i], config, problems, ids, areas, index * 4 + i, region);
}

}  // namespace

LandscapeReport check_all(const LandscapeState& s) {
  LandscapeReport report;
  const NodePtr& root = s.root;
  if (root->box != s.world || root->depth != 0)
    report.problems.push_back("the root is not the world");
  std::set<PolygonId> ids;
  detail::AreaTable areas{};
  check_subtree(root, s.config, report.problems, ids, areas, 0, {});
  if (!s.config.region_ids && !ids.empty() && *ids.rbegin() >= s.next_id)
    report.problems.push_back("an id is not below the next id");
  for (std::size_t m = 1; m < kMaterialCount; ++m)
    if (areas[m] != (*s.areas)[m])
      report.problems.push_back("the area of material " + std::to_string(m) +
                                " is not the sum of its polygons");
  return report;
}

LandscapeInternalError internal_error(const LandscapeState& s, const std::string& what,
                                      const std::string& log_line) {
  std::ostringstream state;
  save_state(s, state);
  return LandscapeInternalError(what, state.str(), replay_log(s) + log_line);
}

}  // namespace edgeland::detail
