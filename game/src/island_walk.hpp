#pragma once
// The polygons of one piece of solid, found from one of its polygons by walking contacts: within
// a cell its group (cell_scan.hpp), across a cell side the groups of the neighbour whose ports
// overlap its ports over a positive length. Reads only the cell records. O(size of the piece x
// log).
#include <vector>

#include "cell_store.hpp"
#include "edgeland/game/islands.hpp"
#include "island_summary.hpp"

namespace edgeland::game_detail {

struct WalkedPolygon {
  PolygonId id = 0;
  Material material = kEmpty;
  const Polygon* ring = nullptr;  // valid while the store keeps the cell's record
  Box64 cell;
};

// Every polygon connected to `start` (a solid polygon of `cell`), ascending by id.
std::vector<WalkedPolygon> walk_piece(const Landscape& world, const CellStore& store,
                                      PolygonId start, const Box64& cell);

// The island a summary closed, walked from its representative.
Island island_of(const Landscape& world, const CellStore& store, const ClosedIsland& closed);

// Those of several, ascending by their smallest polygon id.
std::vector<Island> islands_of(const Landscape& world, const CellStore& store,
                               std::span<const ClosedIsland> closed);

}  // namespace edgeland::game_detail
