#pragma once
// Islands taken out of the landscape as debris (game_types.hpp, Debris): all the islands of one
// update in one Landscape::remove (a carve of exactly their polygons, whose edges are the
// landscape's own, so it meets no crossing and rounds nothing), each island's region merged per
// material into maximal polygons (the body's outline, not the cells it was cut from) and those cut
// into convex pieces.
#include <span>
#include <vector>

#include "edgeland/game/game_types.hpp"
#include "edgeland/game/islands.hpp"

namespace edgeland::game_detail {

struct DetachedAll {
  ChangeSet changes;           // the one carve (empty when no island was present)
  std::vector<Debris> debris;  // one per island detached, in the order given
  std::size_t stale = 0;       // islands skipped: no longer all in the landscape
};

// Whether the landscape still holds every polygon of the island (its id, in the cell holding it
// now); their references are appended to `refs` when it does.
bool present(const Landscape& world, const Island& island, std::vector<PolygonRef>& refs);

// The islands still present, carved out of `world` in one edit (strong guarantee: a throw
// leaves `world` as it was), each made debris (as debris_of).
DetachedAll detach_islands(Landscape& world, std::span<const Island> islands,
                           const GameOptions& options);

// An island's debris (without taking it out of the landscape): pieces of at most
// options.max_piece_vertices, meshes when options.meshes.
Debris debris_of(const Island& island, const GameOptions& options);

}  // namespace edgeland::game_detail
