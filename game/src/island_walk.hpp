#pragma once
// The polygons of one piece of solid, found from one of its polygons by walking contacts: within
// a cell its group (cell_solids.hpp), across a cell side the groups of the neighbour whose ports
// overlap its ports over a positive length. O(size of the piece x log): an island is small.
#include <vector>

#include "cell_solids.hpp"

namespace edgeland::game_detail {

struct WalkedPolygon {
  PolygonId id = 0;
  Material material = kEmpty;
  const Polygon* ring = nullptr;  // valid until the landscape's next edit
  Box64 cell;
};

// Every polygon connected to `start` (a solid polygon of `cell`), ascending by id.
std::vector<WalkedPolygon> walk_piece(const Landscape& world, PolygonId start, const Box64& cell,
                                      const PhysicsMaterials& materials);

}  // namespace edgeland::game_detail
