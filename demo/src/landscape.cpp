#include "edgeland/demo/landscape.hpp"

#include "edgeland/demo/world.hpp"

namespace edgeland::demo {

DemoBuild build_demo(Landscape& landscape, std::uint64_t seed, std::size_t actions) {
  DemoEditor editor(landscape);
  SplitMix64 random(seed);
  DemoBuild build;
  const Terrain terrain = build_world(editor, landscape.world(), random);
  build.world_edits = editor.edits();
  build.actions = run_actions(editor, landscape.world(), terrain, actions, random);
  return build;
}

Landscape demo_landscape(const Box64& box, std::uint64_t seed, std::size_t actions) {
  Landscape landscape(box);
  landscape.start_log();
  build_demo(landscape, seed, actions);
  return landscape;
}

}  // namespace edgeland::demo
