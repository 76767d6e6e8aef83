// Every polygon of a landscape with its cell's corner (landscape_polygons.hpp).
#include "landscape_polygons.hpp"

namespace edgeland::testing {

std::vector<CellPolygon> landscape_polygons(const Landscape& landscape) {
  std::vector<CellPolygon> out;
  landscape.polygons_in(landscape.world(), [&](const PolygonView& view) {
    out.push_back({*view.polygon, view.cell.min});
    return true;
  });
  return out;
}

}  // namespace edgeland::testing
