#include "demo_editor.hpp"
#include "demo_world.hpp"
#include "edgeland/play/session.hpp"
#include "splitmix64.hpp"

namespace edgeland::play {

Landscape demo_landscape(const Box64& box, std::uint64_t seed) {
  Landscape world(box);
  world.start_log();
  cli::demo::DemoEditor editor(world);
  cli::SplitMix64 random(seed);
  cli::demo::build_world(editor, box, random);
  return world;
}

}  // namespace edgeland::play
