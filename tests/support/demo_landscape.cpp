// The demo's world for tests and benchmarks (demo_landscape.hpp).
#include "demo_landscape.hpp"

#include "demo_actions.hpp"
#include "demo_editor.hpp"
#include "demo_world.hpp"
#include "splitmix64.hpp"

namespace edgeland::testing {

Landscape demo_landscape(std::size_t edits, std::uint64_t seed) {
  Landscape landscape(kDemoWorld);
  cli::demo::DemoEditor editor(landscape);
  cli::SplitMix64 random(seed);
  const cli::demo::Terrain terrain = cli::demo::build_world(editor, landscape.world(), random);
  cli::demo::run_actions(editor, landscape.world(), terrain, edits, random);
  return landscape;
}

std::vector<CellPolygon> landscape_polygons(const Landscape& landscape) {
  std::vector<CellPolygon> out;
  landscape.polygons_in(landscape.world(), [&](const PolygonView& view) {
    out.push_back({*view.polygon, view.cell.min});
    return true;
  });
  return out;
}

}  // namespace edgeland::testing
