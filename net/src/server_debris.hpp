#pragma once
// Debris on the server (net/README.md, "Debris travels as a command"): the islands each edit
// leaves, found by the game layer's IslandTracker, detached one by one; each detachment is a carve
// of the island's own polygons, which the server broadcasts as a COMMAND like any edit.
#include <functional>
#include <vector>

#include "edgeland/game/islands.hpp"

namespace edgeland::net {

class ServerDebris {
 public:
  explicit ServerDebris(const Landscape& world) : islands_(world) {}
  // Detaches the islands `changes` (the last edit's) made, and those each detachment makes,
  // calling `detached(before, carve, changes)` after each with the world before it, the carve
  // it was and its change set.
  void detach_all(
      Landscape& world, const ChangeSet& changes,
      const std::function<void(const Landscape&, const Edit&, const ChangeSet&)>& detached);

 private:
  IslandTracker islands_;
};

}  // namespace edgeland::net
