#pragma once
// The page's world: a Session (play/core) plus what the page needs to redraw and rebuild its
// colliders, as flat arrays that cross into JavaScript in one copy each. Floating point appears
// only in the ids' transport type and the timings, never in the world.
#include <cstdint>
#include <string>
#include <vector>

#include "edgeland/play/session.hpp"

namespace edgeland::play {

// What changed, for the page: drop the polygons `removed` (or everything, when `reset`), then
// add polygon k: id ids[k], material materials[k], vertices xy[2 offsets[k] ..
// 2 offsets[k + 1]) as x, y pairs, counter-clockwise.
struct WebUpdate {
  bool reset = false;
  std::vector<double> removed;  // polygon ids; exact in a double below 2^53
  std::vector<double> ids;
  std::vector<std::uint8_t> materials;
  std::vector<std::uint32_t> offsets{0};  // vertex offsets, one more than polygons
  std::vector<std::int32_t> xy;           // |c| <= kCoordBound < 2^31
  std::vector<std::int32_t> cells;        // the cells the edit made: x0, y0, x1, y1 each
  std::string error;                      // a refused edit: the reason; nothing changed
};

struct WebStats {
  std::size_t polygons = 0, vertices = 0, cells = 0, depth = 0, edits = 0;
  double last_edit_ms = 0;   // the last apply(), edit and update together
  double total_edit_ms = 0;  // all apply() calls
};

class WebWorld {
 public:
  // The demo world (seed > 0) or a world filled with `fill` (seed 0), recording its log.
  WebWorld(const Box64& box, Material fill, std::uint64_t seed);

  WebUpdate apply(const ToolEdit& edit);
  WebUpdate undo();
  WebUpdate redo();
  // Everything, as a reset (the page's first draw).
  WebUpdate everything() const;
  // Replaces the world by the one a landscape log describes (up to its first bad line); the
  // update redraws it. The history starts again.
  WebUpdate load_log(std::string_view text);

  // Every cell's box, x0, y0, x1, y1 each (the cell-lines overlay).
  std::vector<std::int32_t> cells() const;
  std::string log() const { return session_.world().log(); }
  std::string state_hash() const;
  WebStats stats() const;
  const Landscape& landscape() const noexcept { return session_.world(); }

 private:
  Session session_;
  std::size_t edits_ = 0;
  double last_edit_ms_ = 0, total_edit_ms_ = 0;
};

}  // namespace edgeland::play
