// Debris islands (islands.hpp): named worlds whose islands are known, and random edit sequences
// against the brute-force reference (island_oracle.hpp), incrementally after every edit.
#include "edgeland/game/islands.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <map>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/canonical_form.hpp"
#include "edgeland/kernel/centroid.hpp"
#include "game_worlds.hpp"
#include "island_oracle.hpp"
#include "landscape_cases.hpp"

namespace edgeland::test {
namespace {

Polygon rect(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

std::set<IdSet> id_sets(const std::vector<Island>& islands) {
  std::set<IdSet> out;
  for (const Island& i : islands) out.insert(ids_of(i));
  return out;
}

// Rock on the floor is held by the world border; a ring carved around a block of it cuts the
// block off: one island, its area exactly the block's.
TEST(Islands, CarvingARingAroundABlockCutsItOff) {
  LandscapeConfig grid;
  grid.grid_depth = 3;
  Landscape world({{0, 0}, {800, 800}}, kEmpty, grid);
  world.fill(PolygonSet{rect(0, 0, 800, 400)}, 1);
  IslandTracker tracker(world);
  EXPECT_EQ(tracker.island_count(), 0u);
  // A square ring 10 wide around [300, 500] x [150, 350], across cell lines.
  const ChangeSet changes =
      world.carve(PolygonSet{rect(290, 140, 510, 150), rect(500, 150, 510, 360),
                             rect(290, 350, 500, 360), rect(290, 150, 300, 350)});
  const std::vector<Island> fresh = tracker.update(world, changes);
  ASSERT_EQ(fresh.size(), 1u);
  EXPECT_EQ(fresh[0].twice_area, Int128{2} * 200 * 200);
  EXPECT_EQ(fresh[0].bounds, (Box64{{300, 150}, {500, 350}}));
  EXPECT_GT(fresh[0].pieces.size(), 1u);  // cut at cell lines
  EXPECT_EQ(id_sets(tracker.islands(world)), islands_brute(world, {}));
}

// A block touching the rest at one corner only is an island; bedrock under a block holds it.
TEST(Islands, PointContactHoldsNothingButAnchoredMaterialDoes) {
  Landscape world({{0, 0}, {100, 100}});
  world.fill(PolygonSet{rect(0, 0, 100, 20)}, 1);
  world.fill(PolygonSet{rect(20, 20, 40, 40)}, 1);  // on the floor: held
  world.fill(PolygonSet{rect(40, 40, 60, 60)}, 2);  // touches the first at (40, 40) only
  world.fill(PolygonSet{rect(70, 50, 90, 70)}, 3);  // bedrock in mid air
  world.fill(PolygonSet{rect(70, 70, 90, 80)}, 2);  // on the bedrock
  PhysicsMaterials materials;
  materials.anchored[3] = true;
  const std::vector<Island> islands = find_islands(world, materials);
  ASSERT_EQ(islands.size(), 1u);
  ASSERT_EQ(islands[0].pieces.size(), 1u);
  EXPECT_EQ(islands[0].pieces[0].material, 2);
  EXPECT_EQ(islands[0].bounds, (Box64{{40, 40}, {60, 60}}));
  // Without the anchor, the bedrock and the dirt on it are an island too.
  EXPECT_EQ(find_islands(world).size(), 2u);
}

PhysicsMaterials random_materials() {
  PhysicsMaterials m;
  for (int k = 1; k < 6; ++k) {
    m.solid[k] = *rc::gen::inRange(0, 5) != 0;
    m.anchored[k] = *rc::gen::inRange(0, 4) == 0;
  }
  return m;
}

RC_GTEST_PROP(IslandsProperty, TrackerFindsExactlyTheNewIslandsAfterEveryEdit, ()) {
  const LandscapeCase c = *landscape_case(10);
  const PhysicsMaterials materials = random_materials();
  Landscape world(c.world, c.fill, c.config);
  IslandTracker tracker(world, materials);
  std::set<IdSet> before = islands_brute(world, materials);
  RC_ASSERT(id_sets(tracker.islands(world)) == before);
  for (const LandscapeEdit& e : c.edits) {
    const ChangeSet changes = apply(world, e);
    const std::vector<Island> fresh = tracker.update(world, changes);
    const std::set<IdSet> after = islands_brute(world, materials);
    std::set<IdSet> expected_new;
    for (const IdSet& s : after)
      if (!before.count(s)) expected_new.insert(s);
    RC_ASSERT(id_sets(fresh) == expected_new);
    RC_ASSERT(id_sets(tracker.islands(world)) == after);
    RC_ASSERT(tracker.island_count() == after.size());
    before = after;
  }
  RC_CLASSIFY(!before.empty(), "islands at the end");
}

// A long game in a layered world: after every edit the tracker's islands are the reference's.
TEST(Islands, TrackerHoldsOverALongGame) {
  LandscapeConfig config;
  config.edge_cap = 32;
  config.merge_below = 12;
  Landscape world = layered_world(2048, config);
  PhysicsMaterials materials;
  materials.anchored[3] = true;
  materials.solid[4] = false;
  IslandTracker tracker(world, materials);
  std::set<IdSet> before = islands_brute(world, materials);
  std::size_t found = 0;
  random_edits(world, 11, 300, [&](const ChangeSet& changes) {
    const std::vector<Island> fresh = tracker.update(world, changes);
    const std::set<IdSet> after = islands_brute(world, materials);
    std::set<IdSet> expected_new;
    for (const IdSet& s : after)
      if (!before.count(s)) expected_new.insert(s);
    ASSERT_EQ(id_sets(fresh), expected_new);
    found += fresh.size();
    before = after;
  });
  EXPECT_EQ(id_sets(tracker.islands(world)), before);
  EXPECT_GT(found, 0u);
}

// Detaching every island of a long game, the loop of islands.hpp: each detach takes away exactly
// its island's area, per material, and leaves no island behind; regions and centroid are exact.
TEST(Islands, DetachTakesAwayExactlyEachIsland) {
  LandscapeConfig config;
  config.edge_cap = 32;
  config.merge_below = 12;
  Landscape world = layered_world(2048, config);
  random_edits(world, 5, 200, [](const ChangeSet&) {});
  PhysicsMaterials materials;
  materials.anchored[3] = true;
  IslandTracker tracker(world, materials);
  std::vector<Island> pending = tracker.islands(world);
  ASSERT_GT(pending.size(), 3u);
  std::size_t detached = 0;
  while (!pending.empty()) {
    const Island island = std::move(pending.back());
    pending.pop_back();
    std::map<Material, Int128> expected;
    for (int m = 0; m < 6; ++m) expected[m] = world.twice_area(m);
    for (const IslandPiece& p : island.pieces) {
      expected[p.material] -= twice_signed_area(p.polygon);
      expected[kEmpty] += twice_signed_area(p.polygon);
    }
    DetachedIsland d;
    try {
      d = detach(world, island);
    } catch (const StaleIsland&) {
      continue;
    }
    ++detached;
    for (int m = 0; m < 6; ++m) EXPECT_EQ(world.twice_area(m), expected[m]) << m;
    Int128 regions = 0;
    PolygonSet pieces;
    for (const DetachedIsland::Region& r : d.regions) regions += twice_signed_area(r.polygons);
    for (const IslandPiece& p : island.pieces) pieces.push_back(p.polygon);
    EXPECT_EQ(regions, island.twice_area);
    EXPECT_EQ(d.twice_area, island.twice_area);
    EXPECT_EQ(d.centroid, centroid(pieces));
    for (Island& again : tracker.update(world, d.changes)) pending.push_back(std::move(again));
  }
  EXPECT_GT(detached, 3u);
  EXPECT_EQ(tracker.island_count(), 0u);
  EXPECT_TRUE(islands_brute(world, materials).empty());
  EXPECT_TRUE(world.check().ok());
  // A stale island is refused and the world is left as it was.
  const std::uint64_t hash = world.state_hash();
  Island gone;
  gone.pieces.push_back({999999, 1, {{0, 0}, {1, 0}, {0, 1}}, world.world()});
  EXPECT_THROW(detach(world, gone), StaleIsland);
  EXPECT_EQ(world.state_hash(), hash);
}

// merge_tiles (the debris' outlines) on what a landscape really holds: each material's polygons
// of a worn landscape, from every cell, in one batch and one by one. Cells' canonical pieces may
// touch where one's corner lies inside another's side; the union then closes holes that touch
// the outside at such a corner (the case MergeTiles.ACornerInsideASideClosingAHoleIsSplitThere
// keeps). Checked mode validates; the region is merge()'s, the area the pieces' sum.
RC_GTEST_PROP(MergeTilesProperty, EachMaterialOfALandscapeMergesToMergesRegion, ()) {
  const LandscapeCase c = *landscape_case(10);
  const Landscape l = run_case(c, c.config);
  std::map<Material, PolygonSet> by_material;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    by_material[v.material].push_back(*v.polygon);
    return true;
  });
  for (auto& [material, pieces] : by_material) {
    const ValidSet tiles(std::move(pieces));
    const ValidClipResult fast = merge_tiles(tiles, {.checked = true});
    RC_ASSERT(is_canonical(fast.set.polygons()));
    RC_ASSERT(twice_signed_area(fast.set.polygons()) == twice_signed_area(tiles.polygons()));
    RC_ASSERT(clip(ClipOp::kXor, fast.set, merge(tiles).set).set.polygons().empty());
  }
  RC_CLASSIFY(by_material.size() > 1, "several materials");
}

}  // namespace
}  // namespace edgeland::test
