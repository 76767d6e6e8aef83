#pragma once
// `edgeland demo --physics`: the demo's physics scenario (demo/physics/physics_scenario.hpp), the
// same one tests/box2d checks, run for a number of frames with PNG frames of the terrain, the
// bodies and the falling debris, and a summary of what it did and where the time went.
#include <cstdint>
#include <string>

namespace edgeland::cli {

struct PhysicsDemoOptions {
  std::string out = ".";  // frames go to OUT/physics_NNNN.png
  int frames = 600;       // frames of edits after the bodies have landed (10 s at 60 Hz)
  int frame_every = 30;   // write every K-th frame
  std::uint64_t seed = 1;
};

// Writes its frames into options.out, which must exist (run_demo makes it). Returns the exit
// status (commands.hpp): 0; 2 when a frame cannot be written.
int run_physics_demo(const PhysicsDemoOptions& options);

}  // namespace edgeland::cli
