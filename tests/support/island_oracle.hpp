#pragma once
// A brute-force reference for debris islands (islands.hpp), from the definition and sharing no
// code with game/: every pair of solid polygons of the whole landscape whose edges lie on each
// other in opposite directions over a positive length is connected (a union-find over all of
// them); a component with an anchored material or an edge on the world border is held.
#include <set>
#include <vector>

#include "edgeland/game/islands.hpp"

namespace edgeland::test {

using IdSet = std::vector<PolygonId>;  // ascending

// The islands as sets of polygon ids.
std::set<IdSet> islands_brute(const Landscape& world, const PhysicsMaterials& materials);

inline IdSet ids_of(const Island& island) {
  IdSet out;
  for (const IslandPiece& p : island.pieces) out.push_back(p.id);
  return out;
}

}  // namespace edgeland::test
