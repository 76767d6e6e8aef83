// PATCH deltas (patch.hpp; spatial/README.md "Deltas, divergence and repair").
#include "patch.hpp"

#include <algorithm>
#include <set>
#include <string>

#include "byte_codec.hpp"
#include "changes.hpp"
#include "check.hpp"
#include "edgeland/kernel/area.hpp"
#include "edit_log.hpp"
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

void add_areas(AreaTable& areas, const NodePtr& subtree, int sign) {
  for_each_cell(subtree, [&](const NodePtr& c) {
    for (std::size_t i = 0; i < c->ids.size(); ++i)
      areas[c->content.labels[i]] += sign * twice_signed_area(c->polygon_set()[i]);
  });
}

// Builds the patched state one entry at a time.
class Patcher {
 public:
  Patcher(const LandscapeState& s, const Delta& d) : s_(s), d_(d), next_(s) {}

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
  void apply_entry(std::size_t i, AreaTable& areas) {
    const PatchEntry& e = d_.patches[i];
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
  }

  // The entry's subtree in the old node's place, every node checked as it is read; its cells
  // and vertices count against the limits with the rest of the world's.
  NodePtr read_subtree(std::size_t i, const Node& old) {
    const std::string& bytes = d_.patches[i].subtree;
    const Node& root = *next_.root;
    ByteReader in(bytes, 0, bytes.size());
    try {
      TreeReader tree(in, s_.config, s_.limits, d_.next_id, root.cells - old.cells,
                      root.vertices - old.vertices);
      NodePtr node = tree.read(old.box, old.depth);
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
  // outside the patched subtrees, and all ids are below the patch's next id.
  void check_ids() {
    std::sort(ids_.begin(), ids_.end());
    if (const auto twice = std::adjacent_find(ids_.begin(), ids_.end()); twice != ids_.end())
      throw DeltaError("patched world: id " + std::to_string(*twice) + " twice", 0);
    check_outside(next_.root);
  }

  void check_outside(const NodePtr& n) const {
    if (patched_.count(n.get())) return;
    if (!n->is_cell()) {
      for (std::uint32_t i = 0; i < n->child_count; ++i) check_outside(n->children[i]);
      return;
    }
    for (const PolygonId id : n->ids) {
      if (std::binary_search(ids_.begin(), ids_.end(), id))
        throw DeltaError("patched world: id " + std::to_string(id) + " twice", 0);
      if (id >= d_.next_id)
        throw DeltaError("patched world: id " + std::to_string(id) + " not below the next id", 0);
    }
  }

  const LandscapeState& s_;
  const Delta& d_;
  LandscapeState next_;
  std::set<const Node*> patched_;
  std::vector<PolygonId> ids_;
};

}  // namespace

EditResult apply_patch(const LandscapeState& state, const Delta& patch) {
  return Patcher(state, patch).run();
}

}  // namespace edgeland::detail
