#pragma once
// Realistic landscape polygons for the tests and benchmarks of the polygon algorithms: the world
// of `edgeland demo` (cli/demo_world.hpp: layers under wavy lines, ore bands, caves, pools) after
// `edits` of its players' explosions, tunnels, floods, veins and landslides.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::testing {

// The demo's 8192 x 8192 world box.
inline constexpr Box64 kDemoWorld{{0, 0}, {8192, 8192}};

// The demo world after `edits` actions, from `seed` (the demo's default is 1).
Landscape demo_landscape(std::size_t edits, std::uint64_t seed = 1);

// Every polygon of the landscape with the corner of its cell (a nearby origin).
struct CellPolygon {
  Polygon polygon;
  Point64 cell_corner;
};
std::vector<CellPolygon> landscape_polygons(const Landscape& landscape);

}  // namespace edgeland::testing
