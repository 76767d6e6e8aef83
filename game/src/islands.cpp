#include "edgeland/game/islands.hpp"

#include <algorithm>
#include <set>

#include "cell_store.hpp"
#include "island_tree.hpp"
#include "island_walk.hpp"

namespace edgeland {

namespace game_detail {

// The tracker's own cell records and summaries, and the landscape last seen (to tell which
// cells a change set's new cells replaced).
struct IslandTrackerState {
  IslandTrackerState(const Landscape& world, const PhysicsMaterials& m)
      : materials(m), seen(world) {
    store.scan(world, all_cells(world), materials);
    tree = std::make_unique<IslandTree>(world, store, materials);
  }
  PhysicsMaterials materials;
  CellStore store;
  std::unique_ptr<IslandTree> tree;
  Landscape seen;
  std::vector<Box64> replaced;
  std::vector<GoneCell> gone;
};

}  // namespace game_detail

using game_detail::IslandTrackerState;

IslandTracker::IslandTracker(const Landscape& world, const PhysicsMaterials& materials)
    : state_(std::make_unique<IslandTrackerState>(world, materials)) {}

IslandTracker::~IslandTracker() = default;
IslandTracker::IslandTracker(IslandTracker&&) noexcept = default;
IslandTracker& IslandTracker::operator=(IslandTracker&&) noexcept = default;

std::vector<Island> IslandTracker::update(const Landscape& world, const ChangeSet& changes) {
  IslandTrackerState& s = *state_;
  game_detail::replaced_cells(s.seen, changes.cells, s.replaced);
  s.gone.clear();
  s.store.remove(s.replaced, s.gone);
  s.store.scan(world, changes.cells, s.materials);
  s.seen = world;
  return game_detail::islands_of(world, s.store, s.tree->update(world, s.store, changes.cells));
}

std::vector<Island> IslandTracker::resync(const Landscape& world) {
  IslandTrackerState& s = *state_;
  std::set<game_detail::IslandKey> before;
  for (const game_detail::ClosedIsland& c : s.tree->islands()) before.insert(c.key);
  state_ = std::make_unique<IslandTrackerState>(world, s.materials);
  std::vector<game_detail::ClosedIsland> fresh;
  for (const game_detail::ClosedIsland& c : state_->tree->islands())
    if (!before.count(c.key)) fresh.push_back(c);
  return game_detail::islands_of(world, state_->store, fresh);
}

std::vector<Island> IslandTracker::islands(const Landscape& world) const {
  return game_detail::islands_of(world, state_->store, state_->tree->islands());
}

std::size_t IslandTracker::island_count() const { return state_->tree->islands().size(); }

IslandTracker::Work IslandTracker::last_work() const {
  return {state_->tree->last_nodes(), state_->tree->last_ports()};
}

std::vector<Island> find_islands(const Landscape& world, const PhysicsMaterials& materials) {
  return IslandTracker(world, materials).islands(world);
}

}  // namespace edgeland
