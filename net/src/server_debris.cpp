#include "server_debris.hpp"

namespace edgeland::net {

// The loop islands.hpp gives: an island another detachment re-cut is stale and comes back from
// the tracker's next update.
void ServerDebris::detach_all(
    Landscape& world, const ChangeSet& changes,
    const std::function<void(const Landscape&, const Edit&, const ChangeSet&)>& detached) {
  std::vector<Island> pending = islands_.update(world, changes);
  while (!pending.empty()) {
    const Island island = std::move(pending.back());
    pending.pop_back();
    const Landscape before = world;
    DetachedIsland d;
    try {
      d = detach(world, island);
    } catch (const StaleIsland&) {
      continue;
    }
    PolygonSet pieces;
    for (const IslandPiece& p : island.pieces) pieces.push_back(p.polygon);
    // detach carved exactly this set (game/src/detach.cpp): the clients' carve is the same.
    detached(before, Edit::carve(ValidSet(std::move(pieces))), d.changes);
    for (Island& again : islands_.update(world, d.changes)) pending.push_back(std::move(again));
  }
}

}  // namespace edgeland::net
