#pragma once
// The page's world: a Session (play/core) over the game driver, and its updates as what the page
// needs to redraw and rebuild its colliders, flat arrays that cross into JavaScript in one copy
// each. Floating point appears only in the ids'
// transport type, the debris centroids and the timings, never in the world.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "edgeland/play/session.hpp"

namespace edgeland::play {

// What changed, for the page (everything first dropped when `reset`):
//  * polygons (drawing): drop `removed`, add polygon k: id ids[k], material materials[k],
//    vertices xy[2 offsets[k] .. 2 offsets[k + 1]) as x, y pairs, counter-clockwise;
//  * surface chains (colliders): drop `chains_removed`, add chain k: id chain_ids[k], points
//    chain_xy[2 chain_offsets[k] .. 2 chain_offsets[k + 1]), closed chain_closed[k], ghosts
//    chain_ghosts[4k .. 4k + 4) (previous x, y, next x, y), solid on the left;
//  * debris (islands detached by this change): island k at centroid debris_centroids[2k, 2k + 1]
//    with convex pieces debris_pieces[k] .. debris_pieces[k + 1], piece j of material
//    piece_materials[j] and vertices piece_xy[2 piece_offsets[j] .. 2 piece_offsets[j + 1])
//    relative to the centroid.
struct WebUpdate {
  bool reset = false;
  std::vector<double> removed;  // polygon ids; exact in a double below 2^53
  std::vector<double> ids;
  std::vector<std::uint8_t> materials;
  std::vector<std::uint32_t> offsets{0};  // vertex offsets, one more than polygons
  std::vector<std::int32_t> xy;           // |c| <= kCoordBound < 2^31
  std::vector<std::int32_t> cells;        // the cells the edit made: x0, y0, x1, y1 each
  std::vector<double> chains_removed, chain_ids;
  std::vector<std::uint8_t> chain_closed;
  std::vector<std::uint32_t> chain_offsets{0};
  std::vector<std::int32_t> chain_xy, chain_ghosts;
  std::vector<double> debris_centroids, piece_xy;
  std::vector<std::uint32_t> debris_pieces{0}, piece_offsets{0};
  std::vector<std::uint8_t> piece_materials;
  std::string error;  // a refused edit: the reason; nothing changed
};

struct WebStats {
  std::size_t polygons = 0, vertices = 0, cells = 0, depth = 0, edits = 0, chains = 0;
  std::size_t islands_detached = 0;
  double last_edit_ms = 0;   // the last apply(): the edit, the trackers and the update
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
  WebUpdate world_swapped(const GameUpdate& update);  // after undo, redo, load

  Session session_;
  std::size_t edits_ = 0, islands_detached_ = 0;
  double last_edit_ms_ = 0, total_edit_ms_ = 0;
};

}  // namespace edgeland::play
