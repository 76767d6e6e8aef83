// SurfaceTracker (surface_tracker.hpp): its own cell records and the chains kept from them
// (surface_state.hpp), for a game that wants chains alone (the game driver keeps them with the
// islands and meshes from one pass).
#include "edgeland/game/surface_tracker.hpp"

#include "cell_store.hpp"
#include "surface_state.hpp"

namespace edgeland {

namespace game_detail {

struct SurfaceTrackerState {
  SurfaceTrackerState(const Landscape& world, const SurfaceOptions& options)
      : surface(options), seen(world) {}
  // `world` after the cells `replaced_boxes` (of `seen`) were replaced by `fresh_boxes`.
  ChainUpdate change(const Landscape& world, std::span<const Box64> replaced_boxes,
                     std::span<const Box64> fresh_boxes) {
    gone.clear();
    store.remove(replaced_boxes, gone);
    store.scan(world, fresh_boxes, surface.options().materials);
    seen = world;
    return surface.update(world, store, gone, fresh_boxes);
  }
  SurfaceState surface;
  CellStore store;
  Landscape seen;
  std::vector<Box64> replaced, fresh;
  std::vector<GoneCell> gone;
};

}  // namespace game_detail

SurfaceTracker::SurfaceTracker(const Landscape& world, const SurfaceOptions& options)
    : state_(std::make_unique<game_detail::SurfaceTrackerState>(world, options)) {
  state_->change(world, {}, game_detail::all_cells(world));
}

SurfaceTracker::~SurfaceTracker() = default;
SurfaceTracker::SurfaceTracker(SurfaceTracker&&) noexcept = default;
SurfaceTracker& SurfaceTracker::operator=(SurfaceTracker&&) noexcept = default;

ChainUpdate SurfaceTracker::update(const Landscape& world, const ChangeSet& changes) {
  game_detail::replaced_cells(state_->seen, changes.cells, state_->replaced);
  return state_->change(world, state_->replaced, changes.cells);
}

ChainUpdate SurfaceTracker::resync(const Landscape& world) {
  game_detail::differing_cells(world, state_->store, state_->replaced, state_->fresh);
  return state_->change(world, state_->replaced, state_->fresh);
}

const std::map<ChainId, SurfaceChain>& SurfaceTracker::chains() const noexcept {
  return state_->surface.chains();
}

const SurfaceOptions& SurfaceTracker::options() const noexcept { return state_->surface.options(); }

}  // namespace edgeland
