#include "cell_polygons.hpp"

namespace edgeland::game_detail {

CellPolygons read_cell(const Landscape& world, const Box64& cell) {
  CellPolygons out;
  out.box = cell;
  world.polygons_in(cell, [&](const PolygonView& v) {
    (v.cell == cell ? out.own : out.around).push_back({v.id, v.material, v.polygon});
    return true;
  });
  return out;
}

std::vector<Box64> all_cells(const Landscape& world) {
  std::vector<Box64> out;
  world.cells_in(world.world(), [&](const CellView& c) {
    out.push_back(c.box);
    return true;
  });
  return out;
}

std::vector<Box64> cells_at(const Landscape& world, Point64 p) {
  std::vector<Box64> out;
  world.cells_in({p, p}, [&](const CellView& c) {
    out.push_back(c.box);
    return true;
  });
  return out;
}

}  // namespace edgeland::game_detail
