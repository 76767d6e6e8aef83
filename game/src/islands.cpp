#include "edgeland/game/islands.hpp"

#include <algorithm>
#include <set>

#include "edgeland/kernel/area.hpp"
#include "island_tree.hpp"
#include "island_walk.hpp"

namespace edgeland {
namespace {

Island island_of(const Landscape& world, const game_detail::ClosedIsland& closed,
                 const PhysicsMaterials& materials) {
  Island out;
  for (const game_detail::WalkedPolygon& p : game_detail::walk_piece(
           world, closed.representative, closed.representative_cell, materials)) {
    out.pieces.push_back({p.id, p.material, *p.ring, p.cell});
    const Box64 b = *bounding_box(*p.ring);
    if (out.pieces.size() == 1)
      out.bounds = b;
    else
      out.bounds.expand(b);
    out.twice_area += twice_signed_area(*p.ring);
  }
  return out;
}

std::vector<Island> islands_of(const Landscape& world,
                               const std::vector<game_detail::ClosedIsland>& closed,
                               const PhysicsMaterials& materials) {
  std::vector<Island> out;
  for (const game_detail::ClosedIsland& c : closed) out.push_back(island_of(world, c, materials));
  std::sort(out.begin(), out.end(), [](const Island& l, const Island& r) {
    return l.pieces.front().id < r.pieces.front().id;
  });
  return out;
}

}  // namespace

IslandTracker::IslandTracker(const Landscape& world, const PhysicsMaterials& materials)
    : tree_(std::make_unique<game_detail::IslandTree>(world, materials)) {}

IslandTracker::~IslandTracker() = default;
IslandTracker::IslandTracker(IslandTracker&&) noexcept = default;
IslandTracker& IslandTracker::operator=(IslandTracker&&) noexcept = default;

std::vector<Island> IslandTracker::update(const Landscape& world, const ChangeSet& changes) {
  return islands_of(world, tree_->update(world, changes.cells), tree_->materials());
}

std::vector<Island> IslandTracker::resync(const Landscape& world) {
  std::set<game_detail::IslandKey> before;
  for (const game_detail::ClosedIsland& c : tree_->islands()) before.insert(c.key);
  tree_ = std::make_unique<game_detail::IslandTree>(world, tree_->materials());
  std::vector<game_detail::ClosedIsland> fresh;
  for (const game_detail::ClosedIsland& c : tree_->islands())
    if (!before.count(c.key)) fresh.push_back(c);
  return islands_of(world, fresh, tree_->materials());
}

std::vector<Island> IslandTracker::islands(const Landscape& world) const {
  return islands_of(world, tree_->islands(), tree_->materials());
}

std::size_t IslandTracker::island_count() const { return tree_->islands().size(); }

IslandTracker::Work IslandTracker::last_work() const {
  return {tree_->last_nodes(), tree_->last_ports()};
}

std::vector<Island> find_islands(const Landscape& world, const PhysicsMaterials& materials) {
  return IslandTracker(world, materials).islands(world);
}

}  // namespace edgeland
