#pragma once
// The demo's landscape in one call, for every program that shows or measures it: `edgeland
// demo`, the front ends' starting world, and the tests' and benchmarks' realistic landscapes.
// The world of world.hpp, then the players' actions of actions.hpp, all from one seed.
#include <cstddef>
#include <cstdint>

#include "edgeland/demo/actions.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::demo {

// The world box of `edgeland demo`, the tests and the benchmarks.
inline constexpr Box64 kDemoWorld{{0, 0}, {8192, 8192}};

// What build_demo did: the edits that built the world, and the actions after them.
struct DemoBuild {
  std::size_t world_edits = 0;
  ActionCounts actions;
};

// Builds the demo world over the landscape's box from `seed` (build_world), then lets `actions`
// edits of the players' actions loose on it (run_actions). Throws what the landscape's edits
// throw. The same seed and counts give the same state_hash.
DemoBuild build_demo(Landscape& landscape, std::uint64_t seed, std::size_t actions);

// A new landscape over `box` (default configuration), recording its edit log from the start so
// that the log replays to it bit for bit, built by build_demo.
Landscape demo_landscape(const Box64& box, std::uint64_t seed, std::size_t actions = 0);

}  // namespace edgeland::demo
