#pragma once
// Realistic landscape polygons for the tests and benchmarks of the polygon algorithms: every
// polygon of a landscape (the demo's world, demo/: edgeland/demo/landscape.hpp) with the corner
// of its cell.
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::testing {

// Every polygon of the landscape with the corner of its cell (a nearby origin).
struct CellPolygon {
  Polygon polygon;
  Point64 cell_corner;
};
std::vector<CellPolygon> landscape_polygons(const Landscape& landscape);

}  // namespace edgeland::testing
