#pragma once
// Islands taken out of the landscape as debris (game_types.hpp, Debris): all the islands of one
// update in one carve, whose edges are the landscape's own (so the carve meets no crossing and
// rounds nothing), each island's region merged per material into maximal polygons (the body's
// outline, not the cells it was cut from) and those cut into convex pieces.
#include <span>
#include <vector>

#include "edgeland/game/game_types.hpp"
#include "edgeland/game/islands.hpp"

namespace edgeland::game_detail {

struct DetachedAll {
  ChangeSet changes;          // the one carve (empty when no island was present)
  std::vector<Debris> debris;  // one per island detached, in the order given
  std::size_t stale = 0;       // islands skipped: no longer all in the landscape
};

// Whether the landscape still holds every polygon of the island (same id, ring and material).
bool present(const Landscape& world, const Island& island);

// The islands still present, carved out of `world` in one edit (strong guarantee: a throw
// leaves `world` as it was), each made debris with pieces of at most `max_piece_vertices`.
DetachedAll detach_islands(Landscape& world, std::span<const Island> islands,
                           std::size_t max_piece_vertices);

// An island's debris (without taking it out of the landscape).
Debris debris_of(const Island& island, std::size_t max_piece_vertices);

}  // namespace edgeland::game_detail
