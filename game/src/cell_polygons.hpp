#pragma once
// One cell as the game layer reads it through the landscape's public queries: its own polygons
// and the polygons of the cells around it that touch its box (whose edges on the cell's sides
// say whether the cell's solid there is covered from across the line).
#include <vector>

#include "edgeland/game/physics_materials.hpp"

namespace edgeland::game_detail {

struct CellPolygon {
  PolygonId id = 0;
  Material material = kEmpty;
  const Polygon* ring = nullptr;  // valid until the landscape's next edit
};

struct CellPolygons {
  Box64 box;
  std::vector<CellPolygon> own;     // the cell's polygons, in the cell's canonical order
  std::vector<CellPolygon> around;  // other cells' polygons whose bounding box meets the box
};

// One polygons_in() over the closed cell box: O(depth + polygons of the cell and its neighbours).
CellPolygons read_cell(const Landscape& world, const Box64& cell);

// The boxes of every cell, in tree order.
std::vector<Box64> all_cells(const Landscape& world);

// The cells whose closed box holds p.
std::vector<Box64> cells_at(const Landscape& world, Point64 p);

}  // namespace edgeland::game_detail
