#include "island_tree.hpp"

#include <algorithm>

#include "edgeland/kernel/scratch.hpp"
#include "edgeland/spatial/tree_boxes.hpp"

namespace edgeland::game_detail {

struct IslandTree::Node {
  Box64 box;
  std::vector<std::unique_ptr<Node>> children;  // none: a cell
  Summary summary;
  bool dirty = true;
};

// The closed islands of all nodes, and what an update took out and put in.
struct IslandTree::Registry {
  std::map<IslandKey, ClosedIsland> all;
  std::vector<IslandKey> removed;
  std::vector<ClosedIsland> added;

  void take_out(const Summary& s) {
    for (const ClosedIsland& c : s.closed) {
      all.erase(c.key);
      removed.push_back(c.key);
    }
  }
  void take_out_all(const Node& n) {
    take_out(n.summary);
    for (const auto& c : n.children) take_out_all(*c);
  }
  void put_in(const Summary& s) {
    for (const ClosedIsland& c : s.closed) {
      all.emplace(c.key, c);
      added.push_back(c);
    }
  }
};

IslandTree::IslandTree(const Landscape& world, const CellStore& store,
                       const PhysicsMaterials& materials)
    : materials_(materials),
      root_(std::make_unique<Node>()),
      registry_(std::make_unique<Registry>()) {
  root_->box = world.world();
  update(world, store, all_cells(world));
}

IslandTree::~IslandTree() = default;

void IslandTree::replace_cell(Node& root, const Box64& cell, const LandscapeConfig& config) {
  Node* n = &root;
  while (true) {
    n->dirty = true;
    if (n->box == cell) {
      for (const auto& c : n->children) registry_->take_out_all(*c);
      n->children.clear();
      return;
    }
    if (n->children.empty()) {  // a cell that split
      for (const Box64& b : child_boxes(n->box, config)) {
        n->children.push_back(std::make_unique<Node>());
        n->children.back()->box = b;
      }
    }
    const auto next = std::find_if(n->children.begin(), n->children.end(),
                                   [&](const auto& c) { return c->box.contains(cell); });
    if (next == n->children.end()) return;  // not a cell of this landscape's tree
    n = next->get();
  }
}

void IslandTree::recompute(Node& n, const CellStore& store) {
  if (!n.dirty) return;
  // The node's old islands go first: a child may close the same island again below it (after a
  // split), and that one must stay.
  registry_->take_out(n.summary);
  for (const auto& c : n.children) recompute(*c, store);
  ++last_nodes_;
  if (n.children.empty()) {
    leaf_summary(store.at(n.box).scan, n.summary);
  } else {
    detail::ScratchVector<Box64> boxes;
    detail::ScratchVector<const Summary*> summaries;
    for (const auto& c : n.children) {
      boxes.push_back(c->box);
      summaries.push_back(&c->summary);
    }
    combine(n.box, boxes, summaries, last_ports_, n.summary);
  }
  registry_->put_in(n.summary);
  n.dirty = false;
}

std::vector<ClosedIsland> IslandTree::update(const Landscape& world, const CellStore& store,
                                             std::span<const Box64> cells) {
  registry_->removed.clear();
  registry_->added.clear();
  last_nodes_ = last_ports_ = 0;
  for (const Box64& cell : cells) replace_cell(*root_, cell, world.config());
  recompute(*root_, store);
  std::sort(registry_->removed.begin(), registry_->removed.end());
  std::vector<ClosedIsland> fresh;
  for (const ClosedIsland& c : registry_->added)
    if (!std::binary_search(registry_->removed.begin(), registry_->removed.end(), c.key))
      fresh.push_back(c);
  return fresh;
}

bool IslandTree::holds(const IslandKey& key) const { return registry_->all.contains(key); }

std::vector<ClosedIsland> IslandTree::islands() const {
  std::vector<ClosedIsland> out;
  for (const auto& [key, island] : registry_->all) out.push_back(island);
  return out;
}

}  // namespace edgeland::game_detail
