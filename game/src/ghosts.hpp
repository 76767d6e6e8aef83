#pragma once
// Stage 4 of the surface (game/README.md): where an open chain goes on. At its last point t the
// surface continues with the chain, in any cell around t, whose first segment is the first one
// clockwise from the way back (the face-tracing rule of chain_tracing.hpp, now over all cells;
// the sweep stops only at the world border, unless that is a wall). Its second point is the
// chain's next ghost. The previous ghost is found the same way counter-clockwise among chains
// ending at the first point. A chain that meets the world border (no wall) goes on in a straight
// line: the ghost continues its end segment.
#include <functional>
#include <vector>

#include "chain_end_table.hpp"
#include "edgeland/game/surface_chains.hpp"

namespace edgeland::game_detail {

// Appends the open chains of the cells around p (every cell whose closed box holds p) that
// start or end at p.
using ChainsAround = std::function<void(Point64 p, std::vector<const SurfaceChain*>& out)>;

// The chain that goes on from chain's last point / leads into its first point, if any.
const SurfaceChain* following(const SurfaceChain& chain, const ChainsAround& around,
                              const Box64& world, bool border_wall);
const SurfaceChain* preceding(const SurfaceChain& chain, const ChainsAround& around,
                              const Box64& world, bool border_wall);

// An open chain's ghosts from the chains around its ends.
struct Ghosts {
  Point64 prev, next;
  friend bool operator==(const Ghosts&, const Ghosts&) = default;
};
Ghosts ghosts_of(const SurfaceChain& chain, const ChainsAround& around, const Box64& world,
                 bool border_wall);

// Sets an open chain's ghosts (ghosts_of; closed chains keep theirs).
void set_ghosts(SurfaceChain& chain, const ChainsAround& around, const Box64& world,
                bool border_wall);

// Where a chain goes on straight: end + (end - before).
Point64 straight_on(Point64 end, Point64 before);

// An index of open chains by their end points (closed chains are not in it): the chains a
// ghost is taken from. The chains must stay where they are while indexed. A point's chains come
// in the order they were added there (`replace` keeps the place): a surface update re-keys kept
// chains in that order, so it decides chain ids. Storage: one flat table (chain_end_table.hpp).
class ChainEndIndex {
 public:
  void add(const SurfaceChain& chain);
  void remove(const SurfaceChain& chain);
  // `to` takes the place of `from` (a chain with the same end points, which may be gone).
  void replace(const SurfaceChain* from, const SurfaceChain& to);
  // Appends the chains with an end at p, in the order they were added.
  void chains_at(Point64 p, std::vector<const SurfaceChain*>& out) const;
  ChainsAround lookup() const;

 private:
  ChainEndTable table_;
};

}  // namespace edgeland::game_detail
