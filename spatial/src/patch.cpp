// PATCH deltas (patch.hpp; spatial/README.md "Deltas, divergence and repair").
#include "patch.hpp"

#include <algorithm>
#include <set>
#include <string>

#include "changes.hpp"
#include "check.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/spatial/byte_codec.hpp"
#include "edit_log.hpp"
#include "regions.hpp"
#include "tree_codec.hpp"
#include "tree_paths.hpp"

namespace edgeland::detail {
namespace {

[[noreturn]] void refuse(std::size_t entry, const std::string& what, std::size_t offset = 0) {
  throw DeltaError("patch entry " + std::to_string(entry) + ": " + what, offset);
}

// Entries in path order; none may be another's or lie below another's (they would be applied
// twice, in an order that matters).
std::vector<std::size_t> entry_order(const Delta& d) {
  std::vector<std::size_t> order(d.patches.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return path_less(d.patches[a].path, d.patches[b].path);
  });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (path_within(d.patches[order[k]].path, d.patches[order[k - 1]].path))
      refuse(order[k], "its path lies within another entry's");
  return order;
}

// Twice the areas of the subtree's polygons, times sign (a stub's from its summary).
void add_areas(AreaTable& areas, const NodePtr& subtree, int sign) {
  for_each_node(subtree, [&](const NodePtr& n) {
    if (n->is_stub())
      for (const auto& [m, a] : n->stub->twice_areas) areas[m.value()] += sign * a;
    if (!n->is_cell()) return;
    for (std::size_t i = 0; i < n->ids.size(); ++i)
      areas[n->content.labels[i]] += sign * twice_signed_area(n->polygon_set()[i]);
  });
}

// Builds the patched state one entry at a time.
class Patcher {
 public:
  Patcher(const LandscapeState& s, const Delta& d)
      : s_(s), d_(d), next_(s), region_ids_(s.config.region_ids) {}

  EditResult run() {
    auto areas = std::make_shared<AreaTable>(*s_.areas);
    for (const std::size_t i : entry_order(d_)) apply_entry(i, *areas);
    check_ancestors();
    check_ids();
    next_.areas = std::move(areas);
    next_.next_id = d_.next_id;
    ++next_.edits;
    if (next_.logging) {
      next_.log.reset();
      append_log(next_, state_log(next_));
    }
    ChangeSet changes = change_set(diff(s_.root, next_.root));
    return {std::move(next_), std::move(changes)};
  }

 private:
  // Whether the entry lies below its region's node (whose counter it then carries).
  bool below_region(const PatchEntry& e) const {
    return regions_on(s_.config) &&
           e.path.size() > static_cast<std::size_t>(s_.config.region_depth);
  }
  TreePath region_of(const TreePath& path) const {
    return TreePath(path.begin(), path.begin() + s_.config.region_depth);
  }

  void apply_entry(std::size_t i, AreaTable& areas) {
    const PatchEntry& e = d_.patches[i];
    const bool own_counter = region_ids_ && below_region(e);
    if ((e.region_next != 0) != own_counter)
      refuse(i, own_counter ? "no id counter for its region" : "an id counter where none applies");
    const std::vector<NodePtr> chain = nodes_on(next_.root, e.path);
    if (chain.empty()) refuse(i, "its path names no node of this world");
    const NodePtr& old = chain.back();
    NodePtr node = read_subtree(i, *old);
    if (node->hash != e.hash)
      throw DeltaMismatch(DeltaMismatch::Field::kNodeHash, e.hash, node->hash);
    add_areas(areas, old, -1);
    add_areas(areas, node, +1);
    patched_.insert(node.get());
    next_.root = replace_node(chain, e.path, std::move(node));
    if (own_counter) set_counter(i, e);
  }

  // The region's node with the entry's counter.
  void set_counter(std::size_t i, const PatchEntry& e) {
    const TreePath path = region_of(e.path);
    const std::uint64_t index = region_index(path);
    if (e.region_next < region_first_id(index) || e.region_next > region_id_end(index))
      refuse(i, "an id counter outside its region's id space");
    const std::vector<NodePtr> chain = nodes_on(next_.root, path);
    const Node& region = *chain.back();
    std::vector<NodePtr> children(region.children.begin(),
                                  region.children.begin() + region.child_count);
    next_.root =
        replace_node(chain, path, make_inner(region.box, region.depth, children, e.region_next));
    touched_regions_.push_back(path);
  }

  // The entry's subtree in the old node's place, every node checked as it is read; its cells
  // and vertices count against the limits with the rest of the world's.
  NodePtr read_subtree(std::size_t i, const Node& old) {
    const PatchEntry& e = d_.patches[i];
    const Node& root = *next_.root;
    ByteReader in(e.subtree, 0, e.subtree.size());
    try {
      TreeReader tree(in, s_.config, s_.limits, d_.next_id, root.cells - old.cells,
                      root.vertices - old.vertices);
      if (region_ids_ && below_region(e))
        tree.set_region(region_index(region_of(e.path)), e.region_next);
      NodePtr node = tree.read(old.box, old.depth, region_index(e.path));
      if (!in.done()) in.fail("bytes left after the subtree");
      tree.check_ids();
      ids_.insert(ids_.end(), tree.ids().begin(), tree.ids().end());
      return node;
    } catch (const ReadFailure& failure) {
      refuse(i, failure.what, failure.offset);
    }
  }

  // The new ancestors keep the tree's rules with their new children (I4, I7, I8), checked once
  // all entries are in (an ancestor of two entries is whole only then).
  void check_ancestors() const {
    std::vector<std::string> problems;
    std::set<const Node*> checked;
    for (const PatchEntry& e : d_.patches) {
      std::vector<NodePtr> chain = nodes_on(next_.root, e.path);
      chain.pop_back();
      for (const NodePtr& n : chain)
        if (checked.insert(n.get()).second) check_inner(*n, s_.config, problems);
    }
    if (!problems.empty()) throw DeltaError("patched world: " + problems.front(), 0);
  }

  // I6 over the world: the patched ids are unique among themselves and against every polygon
  // outside the patched subtrees that could hold the same id, and all ids are below their
  // counter. With ids per region that is the rest of the regions patched below their node
  // (other regions hand out other ids); else every loaded cell, and every unloaded region's id
  // range.
  void check_ids() {
    std::sort(ids_.begin(), ids_.end());
    if (const auto twice = std::adjacent_find(ids_.begin(), ids_.end()); twice != ids_.end())
      throw DeltaError("patched world: id " + std::to_string(*twice) + " twice", 0);
    if (!region_ids_) return check_outside(next_.root, d_.next_id);
    for (const TreePath& path : touched_regions_) {
      const NodePtr region = nodes_on(next_.root, path).back();
      check_outside(region, region->region_next);
    }
  }

  void check_outside(const NodePtr& n, PolygonId below) const {
    if (patched_.count(n.get())) return;
    if (n->is_stub()) return check_stub(*n->stub, below);
    for (std::uint32_t i = 0; i < n->child_count; ++i) check_outside(n->children[i], below);
    for (const PolygonId id : n->ids) check_id(id, below);
  }

  void check_id(PolygonId id, PolygonId below) const {
    if (std::binary_search(ids_.begin(), ids_.end(), id))
      throw DeltaError("patched world: id " + std::to_string(id) + " twice", 0);
    if (id >= below)
      throw DeltaError("patched world: id " + std::to_string(id) + " not below its counter", 0);
  }

  // An unloaded region: its ids are not here, only their range.
  void check_stub(const StubInfo& stub, PolygonId below) const {
    if (stub.max_id == 0) return;
    const auto first = std::lower_bound(ids_.begin(), ids_.end(), stub.min_id);
    if (first != ids_.end() && *first <= stub.max_id)
      throw DeltaError(
          "patched world: id " + std::to_string(*first) + " in the id range of an unloaded region",
          0);
    if (stub.max_id >= below)
      throw DeltaError("patched world: an unloaded region's ids not below the next id", 0);
  }

  const LandscapeState& s_;
  const Delta& d_;
  LandscapeState next_;
  bool region_ids_;
  std::set<const Node*> patched_;
  std::vector<PolygonId> ids_;
  std::vector<TreePath> touched_regions_;  // regions patched below their node (region_ids)
};

}  // namespace

EditResult apply_patch(const LandscapeState& state, const Delta& patch) {
  return Patcher(state, patch).run();
}

}  // namespace edgeland::detail
