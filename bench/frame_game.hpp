#pragma once
// A frame-based game as a new user writes it (issue 35, "Faster than pixels, end to end";
// bench/README.md, "A game, frame by frame"): a 4096 x 4096 world of bedrock, rock and dirt
// under 200 Box2D balls and boxes; every frame 1-3 edits near random bodies (explosions as
// circles and n-gons, capsule tunnels, builders' fills of circles and n-gons), then one Step.
// The same edits go to two games in one process:
//   edgeland: the landscape's edits, the terrain's colliders, debris islands (found, detached,
//             made bodies) and render meshes: everything the library does for a frame;
//   pixel:    the bitmap's edits, the 64 x 64 chunks they meet traced again with OpenCV and
//             their Box2D chain loops rebuilt (pixel_terrain.hpp).
// Each frame's thread CPU time per stage; Step is timed apart (not library work). The edits are
// chosen from the edgeland side's bodies, so both sides see the same shapes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/spatial/material.hpp"

namespace edgeland::bench {

// One edit of a frame: relabel `shape` (one convex polygon) as a carve (to = 0), a fill (to)
// or a replace (from -> to; from = kEmpty means any material).
struct FrameEdit {
  enum class Kind : std::uint8_t { kCarve, kFill };
  Kind kind = Kind::kCarve;
  Polygon shape;
  Material material = kEmpty;
};

// The stages of a frame, in the order they run.
enum FrameStage : std::size_t {
  kFrameEdits,      // edgeland: the landscape's edits
  kFrameColliders,  // edgeland: the terrain's fixtures kept in step
  kFrameIslands,    // edgeland: islands found, detached, made debris bodies
  kFrameMeshes,     // edgeland: render meshes of what changed
  kFramePaint,      // pixel: the bitmap's edits
  kFrameTrace,      // pixel: the touched chunks traced again
  kFrameRebuild,    // pixel: their loops rebuilt
  kFrameEdgeland,   // the edgeland stages' sum
  kFramePixel,      // the pixel stages' sum
  kFrameEdgelandStep,
  kFramePixelStep,
  kFrameStageCount
};
inline constexpr std::array<const char*, kFrameStageCount> kFrameStageNames{
    "edits",   "colliders", "islands", "meshes",        "paint",     "trace",
    "rebuild", "edgeland",  "pixel",   "edgeland_step", "pixel_step"};

struct FrameGameOptions {
  std::uint64_t seed = 0x6A3E;
  std::size_t frames = 3000;
  std::int64_t size = 4096;
  int bodies = 200;
};

// What one run of the game measured: per frame and stage, seconds; and what it did.
struct FrameGameRun {
  std::array<std::vector<double>, kFrameStageCount> seconds;
  std::size_t edits = 0, detached = 0, buried = 0;
  std::size_t debris_fixtures_max = 0, debris_polygons_max = 0;  // the largest debris body
  std::size_t terrain_fixtures = 0, pixel_fixtures = 0;          // at the end
  std::uint64_t state_hash = 0;
  bool landscape_ok = true;
};

// Plays the game once; `edgeland_first` says which side runs first in every frame.
FrameGameRun play_frame_game(const FrameGameOptions& options, bool edgeland_first);

}  // namespace edgeland::bench
