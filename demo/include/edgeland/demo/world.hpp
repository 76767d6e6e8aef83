#pragma once
// The demo's starting world: layers of bedrock, rock and dirt under wavy lines, a grass skin,
// sand pockets and ore bands made by `replace`, caves carved into the rock and pools of water
// in the lowest of them (`fill_empty`). About 50 edits, all from one seeded generator.
#include "edgeland/demo/editor.hpp"
#include "edgeland/demo/shapes.hpp"
#include "edgeland/kernel/splitmix64.hpp"

namespace edgeland::demo {

// Where the layers ended up: the actions aim at the ground below the surface.
struct Terrain {
  WavyLine surface;
  WavyLine rock_top;
};

Terrain build_world(DemoEditor& editor, const Box64& world, SplitMix64& random);

}  // namespace edgeland::demo
