#pragma once
// Debris islands (game/README.md, "Debris islands"): pieces of solid that nothing holds, found
// incrementally from change sets, and detached from the landscape as bodies of their own.
//
// AN ISLAND is a connected component of solid material (PhysicsMaterials), polygons of any solid
// materials connected through shared boundaries of positive length (a cell line, a hole bridge,
// the border between two solid materials), that contains no anchored material and lies on the
// world border nowhere over a positive length. Touching at a single point connects nothing.
//
// INCREMENTAL. The tracker keeps, for every node of the landscape's tree, a summary of the solid
// inside it as seen from outside (which pieces reach which parts of its sides, which are
// anchored) and the islands that close inside it. An edit recomputes the summaries of its cells
// and of their ancestors only: the cost is the ports (solid crossing a cell line) of the
// children of those ancestors, plus the size of each island found, never the whole world.
#include <cstdint>
#include <memory>
#include <vector>

#include "edgeland/game/game_types.hpp"
#include "edgeland/game/physics_materials.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland {

namespace game_detail {
struct IslandTrackerState;
}

struct IslandPiece {
  PolygonId id = 0;
  Material material = kEmpty;
  Polygon polygon;
  Box64 cell;
  friend bool operator==(const IslandPiece&, const IslandPiece&) = default;
};

struct Island {
  std::vector<IslandPiece> pieces;  // the landscape's polygons it is made of, ascending id
  Box64 bounds;
  Int128 twice_area = 0;
  friend bool operator==(const Island&, const Island&) = default;
};

class EDGELAND_EXPORT IslandTracker {
 public:
  // The summaries of every node of `world`. O(N).
  explicit IslandTracker(const Landscape& world, const PhysicsMaterials& materials = {});
  ~IslandTracker();
  IslandTracker(IslandTracker&&) noexcept;
  IslandTracker& operator=(IslandTracker&&) noexcept;

  // `world` after one edit that returned `changes` (every edit, in order, as for
  // SurfaceTracker). Returns the islands that exist now and did not before (a piece cut off, an
  // island split in two, an island grown by a fill), ascending by their smallest id.
  std::vector<Island> update(const Landscape& world, const ChangeSet& changes);
  // `world` after any change (a restored snapshot, a load): everything is summarised again.
  // Returns the islands not known before. O(N).
  std::vector<Island> resync(const Landscape& world);

  // Every island of the landscape last seen (`world` must be it). O(size of the islands).
  std::vector<Island> islands(const Landscape& world) const;
  std::size_t island_count() const;

  // The work of the last update: summaries made and ports matched (the cost bound above).
  struct Work {
    std::size_t summaries = 0, ports = 0;
  };
  Work last_work() const;

 private:
  std::unique_ptr<game_detail::IslandTrackerState> state_;
};

// Every island of a landscape. O(N).
EDGELAND_EXPORT std::vector<Island> find_islands(const Landscape& world,
                                                 const PhysicsMaterials& materials = {});

// An island taken out of the landscape, ready to become a dynamic body.
struct DetachedIsland {
  ChangeSet changes;  // the edit that removed it (as any edit's: for the trackers)
  using Region = IslandRegion;
  std::vector<Region> regions;  // ascending material
  Int128 twice_area = 0;        // of the whole island, exact
  RationalPoint centroid;       // of the whole island, exact (kernel centroid())
};

// The island's polygons are no longer all in the landscape (it changed since the island was
// found): `polygon` is the first one missing.
class EDGELAND_EXPORT StaleIsland : public Error {
 public:
  explicit StaleIsland(PolygonId polygon);
  PolygonId polygon;
};

// Removes the island from the landscape as one edit: a carve of exactly its region. The island's
// edges lie on the landscape's own edges, so that carve meets no crossing, rounds nothing and
// leaves every other polygon's region as it was. Strong guarantee (a throw leaves the landscape as
// it was): throws StaleIsland, or what a carve throws. O(island size x log).
//
// Pass the returned changes to every tracker, as for any edit. Detaching one of several islands
// an edit created can re-cut the cells another one lies in; that one is then stale (detach
// throws StaleIsland) and IslandTracker::update reports it again, re-cut:
//   std::vector<Island> pending = islands.update(world, changes);
//   while (!pending.empty()) {
//     Island island = std::move(pending.back());
//     pending.pop_back();
//     DetachedIsland d;
//     try { d = detach(world, island); } catch (const StaleIsland&) { continue; }
//     surface.update(world, d.changes);
//     for (Island& again : islands.update(world, d.changes)) pending.push_back(std::move(again));
//     ... a dynamic body from d ...
//   }
EDGELAND_EXPORT DetachedIsland detach(Landscape& world, const Island& island);

}  // namespace edgeland
