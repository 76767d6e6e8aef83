#pragma once
// The pixel pipeline a game runs where edgeland's game layer would be (issue 26, "Speed";
// bench/README.md, "Game layer"): the world is a bitmap (bitmap_world.hpp) cut into 64 x 64
// chunks, and after an edit every chunk the edit's box meets is traced again: OpenCV's
// findContours on the chunk's solid squares, approxPolyDP on each contour, and the chunk's Box2D
// fixtures replaced by b2ChainShape loops of the simplified contours (as DTerrain or
// pixel-perfect for Phaser + Box2D do it). The static bodies are grouped as box2d::Terrain groups
// edgeland's chains (adapters/README.md): one per region of a 16 x 16 grid over the world, since
// Box2D's DestroyFixture walks its body's fixture list (one body for the world would make every
// chunk's replacement walk all the world's loops) and b2World::Step walks every body (a body
// per chunk, 16,384 in the bench, would cost a frame 0.5 ms).
//
// Each chunk is traced alone, padded with empty squares, so its loops close along the chunk's
// sides: solid crossing a chunk line becomes two loops meeting there, the seams edgeland's
// chains avoid (a body sliding over them snags). Contour points are the centres of the solid
// boundary squares; outer loops run counter-clockwise and hole loops clockwise (solid on the
// left, as edgeland's chains), so Box2D's one-sided edges face the empty side. The loops carry no
// material (friction per material would need one tracing per material).
#include <box2d/box2d.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "bitmap_world.hpp"

namespace edgeland::bench {

class PixelTerrain {
 public:
  static constexpr std::int64_t kChunk = 64;

  struct Options {
    std::array<bool, kMaterialCount> solid{};  // by Material::value(): these squares are solid
    double units_per_metre = 32;               // bitmap squares per Box2D metre
    double epsilon = 1.0;                      // approxPolyDP's tolerance, in squares
    std::int64_t body_grid = 16;               // regions per side, a static body each
  };

  // The loops of one chunk, in bitmap squares relative to the world's corner.
  struct ChunkLoops {
    std::size_t chunk = 0;
    std::vector<std::vector<cv::Point>> loops;
  };

  // Traces every chunk of `bitmap` and creates the bodies and loops.
  PixelTerrain(b2World& world, const BitmapWorld& bitmap, const Options& options);
  ~PixelTerrain();
  PixelTerrain(const PixelTerrain&) = delete;
  PixelTerrain& operator=(const PixelTerrain&) = delete;

  // Stage 1: the chunks meeting `box` (world coordinates; the squares an edit inside it can
  // change) traced again. The result lives until the next call.
  const std::vector<ChunkLoops>& trace(const BitmapWorld& bitmap, const Box64& box);
  // Stage 2: those chunks' fixtures destroyed and their loops created.
  void rebuild(const std::vector<ChunkLoops>& traced);

  std::size_t fixture_count() const;
  std::size_t vertex_count() const;

 private:
  void trace_chunk(const BitmapWorld& bitmap, std::int64_t cx, std::int64_t cy, ChunkLoops& out);

  b2World& world_;
  Options options_;
  std::int64_t chunks_x_ = 0, chunks_y_ = 0;
  std::vector<b2Body*> bodies_;                    // per region, row by row
  std::vector<std::size_t> region_;                // per chunk (cy * chunks_x_ + cx): its region
  std::vector<std::vector<b2Fixture*>> fixtures_;  // per chunk
  // Scratch kept between edits, as a game would.
  std::array<std::uint8_t, kMaterialCount> mask_value_{};
  cv::Mat mask_;
  std::vector<std::vector<cv::Point>> contours_;
  std::vector<cv::Vec4i> hierarchy_;
  std::vector<ChunkLoops> traced_;
  std::vector<b2Vec2> vertices_;
};

}  // namespace edgeland::bench
