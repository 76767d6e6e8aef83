#pragma once
// What the demo's players do to the world: explosions (carved rough n-gons), tunnels (capsule
// strokes along random walks, one carve per step), floods (fill_empty water), ore veins
// (replace rock by ore along short walks), landslides (fill dirt) and sand drifts
// (fill_empty sand), until `edits` more edits have been made.
#include <cstddef>

#include "edgeland/demo/editor.hpp"
#include "edgeland/demo/world.hpp"
#include "edgeland/kernel/splitmix64.hpp"

namespace edgeland::demo {

// How many edits of each kind were made (a tunnel or a vein counts once per step).
struct ActionCounts {
  std::size_t explosions = 0, tunnel_steps = 0, floods = 0, vein_steps = 0, landslides = 0,
              drifts = 0;
};

ActionCounts run_actions(DemoEditor& editor, const Box64& world, const Terrain& terrain,
                         std::size_t edits, SplitMix64& random);

}  // namespace edgeland::demo
