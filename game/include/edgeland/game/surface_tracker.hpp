#pragma once
// The collision surface kept in step with a landscape from its change sets (game/README.md,
// "Keeping chains in step"): after an edit, the chains to remove and to add, so that a physics
// engine's static terrain changes only where the edit did. Applying the updates to a mirror of
// the chains gives exactly the chains of a full export (surface_chains()) after every edit.
//
// WHAT CHANGES. An edit replaces the content of some cells (ChangeSet::cells). Their chains are
// new. The chains of the cells touching them are computed again: a side of theirs may be covered
// or uncovered from across, or a ghost may point into a changed cell; only the ones that differ
// are replaced. The cells touching those keep their chains' points (a cell's chains depend on its
// own content and its neighbours') but a ghost of theirs may move; those chains are replaced too.
// Cost: O((changed cells + their neighbours) x cell size) per edit, plus a tree descent per chain
// end near them; nothing depends on the world's size.
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "edgeland/game/surface_chains.hpp"

namespace edgeland {

namespace game_detail {
struct SurfaceTrackerState;
}

class EDGELAND_EXPORT SurfaceTracker {
 public:
  // Every chain of `world` (surface_chains()), numbered from 1. O(N log N).
  explicit SurfaceTracker(const Landscape& world, const SurfaceOptions& options = {});
  ~SurfaceTracker();
  SurfaceTracker(SurfaceTracker&&) noexcept;
  SurfaceTracker& operator=(SurfaceTracker&&) noexcept;

  // `world` after one edit that returned `changes`. Every edit since the tracker was made (or
  // last updated) must be passed, in order, each with the landscape right after it; a landscape
  // changed otherwise (a snapshot restored, a save loaded) takes resync(). Ids are never reused.
  ChainUpdate update(const Landscape& world, const ChangeSet& changes);

  // `world` after any change at all (an undo to a snapshot, a load): the cells whose polygons
  // differ from those last seen are found by comparing every cell's polygons. O(N).
  ChainUpdate resync(const Landscape& world);

  const std::map<ChainId, SurfaceChain>& chains() const noexcept;
  const SurfaceOptions& options() const noexcept;

 private:
  std::unique_ptr<game_detail::SurfaceTrackerState> state_;
};

}  // namespace edgeland
