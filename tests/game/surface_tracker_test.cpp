// SurfaceTracker (surface_tracker.hpp): a mirror of the chains kept only from the updates equals
// a full export after every edit of random edit sequences; only the chains near an edit change.
#include "edgeland/game/surface_tracker.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <map>

#include "game_worlds.hpp"
#include "landscape_cases.hpp"

namespace edgeland::test {
namespace {

using Mirror = std::map<ChainId, SurfaceChain>;

void apply_update(Mirror& mirror, const ChainUpdate& u) {
  for (ChainId id : u.removed) {
    if (mirror.erase(id) != 1u) RC_FAIL("removed an unknown chain " + std::to_string(id));
  }
  for (const auto& [id, chain] : u.added) {
    if (!mirror.emplace(id, chain).second) RC_FAIL("added a known chain " + std::to_string(id));
  }
}

// Chains as a sorted list of values (ids aside), for comparing with a full export.
std::vector<SurfaceChain> values(const Mirror& m) {
  std::vector<SurfaceChain> out;
  for (const auto& [id, c] : m) out.push_back(c);
  return out;
}

bool chain_less(const SurfaceChain& l, const SurfaceChain& r) {
  auto key = [](const SurfaceChain& c) {
    return std::tie(c.cell.min, c.cell.max, c.points, c.materials, c.closed, c.ghost_prev,
                    c.ghost_next);
  };
  return key(l) < key(r);
}

std::vector<SurfaceChain> sorted(std::vector<SurfaceChain> v) {
  std::sort(v.begin(), v.end(), chain_less);
  return v;
}

SurfaceOptions random_options() {
  SurfaceOptions options;
  options.border_wall = *rc::gen::arbitrary<bool>();
  for (int m = 1; m < 6; ++m) options.materials.solid[m] = *rc::gen::inRange(0, 4) != 0;
  return options;
}

RC_GTEST_PROP(SurfaceTrackerProperty, MirrorOfUpdatesEqualsAFullExportAfterEveryEdit, ()) {
  const LandscapeCase c = *landscape_case(10);
  const SurfaceOptions options = random_options();
  Landscape world(c.world, c.fill, c.config);
  SurfaceTracker tracker(world, options);
  Mirror mirror = tracker.chains();
  RC_ASSERT(sorted(values(mirror)) == sorted(surface_chains(world, options)));
  for (const LandscapeEdit& e : c.edits) {
    const ChangeSet changes = apply(world, e);
    const ChainUpdate u = tracker.update(world, changes);
    RC_ASSERT(std::is_sorted(u.removed.begin(), u.removed.end()));
    if (changes.empty()) RC_ASSERT(u.empty());
    apply_update(mirror, u);
    RC_ASSERT(mirror == tracker.chains());
    RC_ASSERT(sorted(values(mirror)) == sorted(surface_chains(world, options)));
  }
  RC_CLASSIFY(world.stats().cells > 1, "several cells");
}

RC_GTEST_PROP(SurfaceTrackerProperty, ResyncFollowsARestoredSnapshot, ()) {
  const LandscapeCase c = *landscape_case(8);
  const SurfaceOptions options = random_options();
  Landscape world(c.world, c.fill, c.config);
  SurfaceTracker tracker(world, options);
  Mirror mirror = tracker.chains();
  std::vector<Landscape> snapshots{world};
  for (const LandscapeEdit& e : c.edits) {
    apply(world, e);
    snapshots.push_back(world);
  }
  // Jump around the history: forward to the end, back to a random snapshot, and on.
  for (int k = 0; k < 4; ++k) {
    const Landscape& target = snapshots[*rc::gen::inRange<std::size_t>(0, snapshots.size())];
    apply_update(mirror, tracker.resync(target));
    RC_ASSERT(sorted(values(mirror)) == sorted(surface_chains(target, options)));
  }
}

// A carve far from a long floor replaces only chains near it.
TEST(SurfaceTracker, AnEditReplacesOnlyChainsNearIt) {
  LandscapeConfig grid;
  grid.grid_depth = 5;  // 32 x 32 cells of 64 units
  Landscape world({{0, 0}, {2048, 2048}}, kEmpty, grid);
  world.fill(PolygonSet{{{0, 0}, {2048, 0}, {2048, 1000}, {0, 1000}}}, 1);
  SurfaceTracker tracker(world);
  const std::size_t before = tracker.chains().size();
  EXPECT_EQ(before, 32u);  // the floor, cut at 32 cells
  const ChangeSet changes =
      world.carve(PolygonSet{{{500, 990}, {520, 990}, {520, 1010}, {500, 1010}}});
  const ChainUpdate u = tracker.update(world, changes);
  // The notch's cell gets a new chain; the cells beside it keep their points but their ghosts
  // at the shared corners now point down the notch... only where the notch reaches the line.
  EXPECT_FALSE(u.added.empty());
  EXPECT_LE(u.added.size(), 4u);
  EXPECT_EQ(u.removed.size(), u.added.size());
  EXPECT_EQ(tracker.chains().size(), before);
}

// An edit replaces only the chains that changed, even in the cell it re-cuts: two holes carved
// into one cell keep their chains (ids and all) when a third hole is carved beside them.
TEST(SurfaceTracker, AnEditKeepsTheUnchangedChainsOfItsCell) {
  LandscapeConfig grid;
  grid.grid_depth = 2;  // 4 x 4 cells of 64 units
  Landscape world({{0, 0}, {256, 256}}, 1, grid);
  world.carve(PolygonSet{{{70, 70}, {76, 70}, {76, 76}, {70, 76}},
                         {{100, 70}, {106, 70}, {106, 76}, {100, 76}}});
  SurfaceTracker tracker(world);
  ASSERT_EQ(tracker.chains().size(), 2u);  // two closed loops in the cell (64 64 128 128)
  const auto kept = tracker.chains();
  const ChangeSet changes = world.carve(PolygonSet{{{80, 100}, {86, 100}, {86, 106}, {80, 106}}});
  ASSERT_EQ(changes.cells, (std::vector<Box64>{{{64, 64}, {128, 128}}}));
  const ChainUpdate u = tracker.update(world, changes);
  EXPECT_TRUE(u.removed.empty());
  ASSERT_EQ(u.added.size(), 1u);
  EXPECT_TRUE(u.added.front().second.closed);
  EXPECT_EQ(u.added.front().second.points.size(), 4u);
  for (const auto& [id, chain] : kept) EXPECT_EQ(tracker.chains().at(id), chain);
}

// A long game: hundreds of edits in a layered world whose cells split and merge all the time,
// with and without a wall, water not solid; the mirror is checked against a full export.
TEST(SurfaceTracker, MirrorHoldsOverALongGame) {
  for (const bool wall : {false, true}) {
    LandscapeConfig config;
    config.edge_cap = 32;
    config.merge_below = 12;
    Landscape world = layered_world(2048, config);
    SurfaceOptions options;
    options.border_wall = wall;
    options.materials.solid[4] = false;
    SurfaceTracker tracker(world, options);
    Mirror mirror = tracker.chains();
    int edit = 0;
    random_edits(world, wall ? 7 : 8, 400, [&](const ChangeSet& changes) {
      const ChainUpdate u = tracker.update(world, changes);
      for (ChainId id : u.removed) ASSERT_EQ(mirror.erase(id), 1u);
      for (const auto& [id, chain] : u.added) ASSERT_TRUE(mirror.emplace(id, chain).second);
      if (++edit % 50 == 0) {
        ASSERT_EQ(sorted(values(mirror)), sorted(surface_chains(world, options)))
            << "edit " << edit;
      }
    });
    EXPECT_GT(world.stats().cells, 100u);
    EXPECT_EQ(sorted(values(mirror)), sorted(surface_chains(world, options)));
  }
}

}  // namespace
}  // namespace edgeland::test
