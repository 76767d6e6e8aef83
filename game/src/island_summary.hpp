#pragma once
// Connectivity summaries for debris islands (game/README.md, "Debris islands"). For a node of the
// landscape's tree, the pieces of solid inside its box as far as the outside can tell: the
// GROUPS that reach its sides, each with its ports (solid along a side), whether it is anchored
// (anchored material or the world border inside), and a fingerprint of its polygon ids; plus the
// groups that CLOSED here: no port left, not anchored, so no solid outside the node touches them.
// Those are the islands. A node's summary is made from its children's alone (their ports along
// the lines between them are matched: solid on both sides of a line over a positive length is
// one piece), so an edit recomputes the summaries on the paths from its cells to the root and
// nothing else. Cost: the ports of the children of those nodes.
#include <array>
#include <compare>
#include <cstdint>
#include <span>
#include <vector>

#include "cell_scan.hpp"

namespace edgeland::game_detail {

// A fingerprint of a set of polygon ids (ids are unique and never reused): equal sets, equal
// keys; merging two sets adds their keys.
struct IslandKey {
  PolygonId min_id = 0;
  std::uint64_t count = 0, sum = 0, mix = 0;  // sums wrap around
  friend auto operator<=>(const IslandKey&, const IslandKey&) = default;
  static IslandKey of(PolygonId id);
  void add(const IslandKey& other);
};

struct Group {
  bool anchored = false;
  IslandKey key;
  PolygonId representative = 0;  // one polygon of the group, and its cell
  Box64 representative_cell;
};

struct ClosedIsland {
  IslandKey key;
  PolygonId representative = 0;
  Box64 representative_cell;
};

// Three arrays, the four sides' ports side by side in one: an update reads the summaries on the
// paths to the root, each cold in the cache, so fewer arrays are fewer misses.
struct Summary {
  std::vector<Port> ports;  // side by side in kSides order; each ascending; group indexes `groups`
  std::array<std::uint32_t, 5> side_begin{};  // side s: ports[side_begin[s], side_begin[s + 1])
  std::vector<Group> groups;                  // the groups with ports
  std::vector<ClosedIsland> closed;           // unanchored groups without ports

  std::span<const Port> side(Side s) const {
    const auto k = static_cast<std::size_t>(s);
    return std::span<const Port>(ports).subspan(side_begin[k], side_begin[k + 1] - side_begin[k]);
  }
};

// A cell's summary from its scan, written over `out` (its storage reused). O(polygons).
void leaf_summary(const CellScan& cell, Summary& out);

// A node's summary from its children's (boxes and summaries in the tree's order), written over
// `out` (its storage reused; not one of the children's). O(ports of the children). `matched`
// counts the ports looked at.
void combine(const Box64& node, std::span<const Box64> children,
             std::span<const Summary* const> summaries, std::size_t& matched, Summary& out);

}  // namespace edgeland::game_detail
