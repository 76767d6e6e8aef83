#pragma once
// Stage 4 of the surface (game/README.md): where an open chain goes on. At its last point t the
// surface continues with the chain, in any cell around t, whose first segment is the first one
// clockwise from the way back (the face-tracing rule of chain_tracing.hpp, now over all cells;
// the sweep stops only at the world border, unless that is a wall). Its second point is the
// chain's next ghost. The previous ghost is found the same way counter-clockwise among chains
// ending at the first point. A chain that meets the world border (no wall) goes on in a straight
// line: the ghost continues its end segment.
#include <cstddef>
#include <optional>
#include <unordered_map>
#include <vector>

#include "edgeland/game/surface_chains.hpp"

namespace edgeland::game_detail {

// The open chains of a set of cells by their end points.
class ChainEnds {
 public:
  void add(const SurfaceChain& chain);
  // The chain (among those added) that goes on from chain's last point, if any.
  const SurfaceChain* following(const SurfaceChain& chain, const Box64& world,
                                bool border_wall) const;
  // The chain that leads into chain's first point, if any.
  const SurfaceChain* preceding(const SurfaceChain& chain, const Box64& world,
                                bool border_wall) const;

 private:
  std::unordered_map<Point64, std::vector<const SurfaceChain*>, Point64Hash> starting_, ending_;
};

// Sets an open chain's ghosts from the chains around its ends (closed chains keep theirs).
void set_ghosts(SurfaceChain& chain, const ChainEnds& ends, const Box64& world, bool border_wall);

}  // namespace edgeland::game_detail
