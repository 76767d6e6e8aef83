#pragma once
// Islands taken out of the landscape as debris (game_types.hpp, Debris): all the islands whose
// debris jobs (debris_job.hpp) finished in one update in one Landscape::remove (a carve of exactly
// their polygons, whose edges are the landscape's own, so it meets no crossing and rounds nothing).
#include <span>
#include <vector>

#include "debris_job.hpp"
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

// The finished jobs' islands still present carved out of `world` in one edit (strong
// guarantee: a throw leaves `world` as it was), their debris taken from the jobs.
DetachedAll detach_finished(Landscape& world, std::span<DebrisJob> jobs);

// Each material's part of the island as maximal polygons (ascending material).
std::vector<IslandRegion> island_regions(const Island& island, bool checked);

}  // namespace edgeland::game_detail
