#pragma once
// The island summaries on a copy of the landscape's tree shape (island_summary.hpp), kept in step
// from change sets: a changed cell's summary is made anew and so are its ancestors'; a cell that
// split becomes a node over its children, a node whose children merged becomes a cell. Every
// closed island of every node is in one registry; an update reports the islands that entered it
// and were not in it before.
#include <map>
#include <memory>
#include <vector>

#include "cell_store.hpp"
#include "island_summary.hpp"

namespace edgeland::game_detail {

class IslandTree {
 public:
  // The summaries of every cell of `world` (each with a record in `store`).
  IslandTree(const Landscape& world, const CellStore& store, const PhysicsMaterials& materials);
  ~IslandTree();

  // The landscape after an edit whose ChangeSet::cells are `cells`. Returns the islands that are
  // new (not closed anywhere in the tree before).
  std::vector<ClosedIsland> update(const Landscape& world, const CellStore& store,
                                   std::span<const Box64> cells);

  // Every island.
  std::vector<ClosedIsland> islands() const;
  // Whether the island of this key is closed now (an edit that changed its polygons or tied it
  // to anchored ground took it out).
  bool holds(const IslandKey& key) const;
  // What the last update did: summaries made, ports looked at.
  std::size_t last_nodes() const { return last_nodes_; }
  std::size_t last_ports() const { return last_ports_; }
  const PhysicsMaterials& materials() const { return materials_; }

 private:
  struct Node;
  struct Registry;

  void replace_cell(Node& root, const Box64& cell, const LandscapeConfig& config);
  void recompute(Node& node, const CellStore& store);

  PhysicsMaterials materials_;
  std::unique_ptr<Node> root_;
  std::unique_ptr<Registry> registry_;
  std::size_t last_nodes_ = 0, last_ports_ = 0;
};

}  // namespace edgeland::game_detail
