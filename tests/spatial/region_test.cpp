// Regions (issue 37, items 4 and 6; spatial/README.md "Regions"): a tree split down to the region
// depth and never merged above it, ids per region, stubs that keep hash, areas and counts,
// RegionNotLoaded, region records in and out, worlds made of stubs, and regions edited apart
// (two owners) that come together as the one-process world.
#include <gtest/gtest.h>

#include <sstream>

#include "edgeland/spatial/delta.hpp"
#include "pinned_sequence.hpp"

namespace edgeland {
namespace {

LandscapeConfig region_config(int depth = 3, bool ids = true) {
  LandscapeConfig c;
  c.region_depth = depth;
  c.region_ids = ids;
  return c;
}

// The pinned sequence's edits (blobs of radius 20-140, every kind) on a world with regions.
Landscape edited(const LandscapeConfig& config, int edits = 300) {
  Landscape l({{0, 0}, {4096, 4096}}, 1, config);
  std::uint64_t seed = 37;
  for (int i = 0; i < edits; ++i) {
    const Point64 c{static_cast<std::int64_t>(pinned::splitmix64(seed) % 4400) - 150,
                    static_cast<std::int64_t>(pinned::splitmix64(seed) % 4400) - 150};
    const PolygonSet shape{
        pinned::blob(c, 20 + static_cast<std::int64_t>(pinned::splitmix64(seed) % 120))};
    if (i % 3 == 0)
      l.fill(shape, 2 + i % 2);
    else
      l.carve(shape);
  }
  return l;
}

std::string record_of(const Landscape& l, const TreePath& path) {
  std::ostringstream out;
  l.save_region(path, out);
  return out.str();
}

void load_record(Landscape& l, const std::string& record) {
  std::istringstream in(record);
  l.load_region(in);
}

// A comb across the world: a band from x = 20 to 4070 whose top edge has 150 teeth (303 vertices:
// an edit big enough to be cut to its cells first, shape_cut.hpp).
Polygon comb(std::int64_t y, std::int64_t height) {
  Polygon p{{20, y}, {4070, y}};
  for (std::int64_t k = 0; k < 150; ++k) {
    p.push_back({4070 - 27 * k, y + height});
    p.push_back({4070 - 27 * k - 13, y + height + 20});
  }
  p.push_back({20, y + height});
  return p;
}

std::uint32_t index_of(const TreePath& path) {
  std::uint32_t index = 0;
  for (const std::uint8_t d : path) index = index * 4 + d;
  return index;
}

TEST(RegionConfig, ADepthOutOfRangeOrIdsWithoutRegionsAreRefused) {
  const Box64 world{{0, 0}, {4096, 4096}};
  const auto refused = [&](const LandscapeConfig& c, InvalidConfig::Setting setting) {
    try {
      Landscape l(world, 1, c);
      ADD_FAILURE() << "accepted";
    } catch (const InvalidConfig& e) {
      EXPECT_EQ(e.setting, setting);
    }
  };
  refused(region_config(11), InvalidConfig::Setting::kRegionDepth);
  refused(region_config(-2), InvalidConfig::Setting::kRegionDepth);
  refused(region_config(9), InvalidConfig::Setting::kRegionDepth);  // 4096 / 2^9 < 16: no split
  LandscapeConfig grid = region_config(3);
  grid.grid_depth = 2;
  refused(grid, InvalidConfig::Setting::kRegionDepth);
  refused(region_config(-1, true), InvalidConfig::Setting::kRegionIds);
  EXPECT_NO_THROW(Landscape(world, 1, region_config(8)));
}

// Off by default, and off means off: the options do not enter the hashes, so every pinned hash
// stands (LandscapeDeterminism); on, they do.
TEST(RegionConfig, TheOptionsEnterTheHashesOnlyWhenOn) {
  const Landscape plain({{0, 0}, {4096, 4096}}, 1);
  EXPECT_EQ(LandscapeConfig().region_depth, -1);
  EXPECT_FALSE(LandscapeConfig().region_ids);
  EXPECT_NE(Landscape({{0, 0}, {4096, 4096}}, 1, region_config(0, false)).world_hash(),
            plain.world_hash());
  EXPECT_NE(Landscape({{0, 0}, {4096, 4096}}, 1, region_config(0, false)).state_hash(),
            plain.state_hash());
}

TEST(Regions, TheTreeSplitsToTheRegionDepthAndNeverMergesAboveIt) {
  Landscape l = edited(region_config(3), 200);
  // Carving everything away would merge the whole tree into one cell without regions.
  l.carve(PolygonSet{{{0, 0}, {4096, 0}, {4096, 4096}, {0, 4096}}});
  EXPECT_EQ(l.region_paths().size(), 64u);
  std::size_t cells = 0;
  l.cells_in(l.world(), [&](const CellView& c) {
    EXPECT_GE(c.depth, 3u);
    ++cells;
    return true;
  });
  EXPECT_EQ(cells, 64u);
  EXPECT_TRUE(l.check().ok());
}

// Every id lies in its region's space, below the counter the region's node keeps.
TEST(Regions, EveryRegionHandsOutIdsOfItsOwn) {
  const Landscape l = edited(region_config(3));
  std::size_t seen = 0;
  for (const TreePath& path : l.region_paths()) {
    const RegionSummary s = l.region_summary(path);
    const std::uint64_t index = index_of(path);
    EXPECT_EQ(s.next_id >> kRegionIdBits, index);
    l.polygons_in(l.node_digest(path)->box, [&](const PolygonView& v) {
      if (!l.node_digest(path)->box.contains(v.cell)) return true;
      EXPECT_EQ(v.id >> kRegionIdBits, index);
      EXPECT_LT(v.id, s.next_id);
      ++seen;
      return true;
    });
  }
  EXPECT_EQ(seen, l.stats().polygons);
  EXPECT_TRUE(l.check().ok());
}

TEST(Regions, AStubKeepsTheHashTheAreasAndTheCounts) {
  Landscape l = edited(region_config(3));
  const std::uint64_t hash = l.state_hash();
  const LandscapeStats stats = l.stats();
  std::vector<Int128> areas;
  for (int m = 0; m < 4; ++m) areas.push_back(l.twice_area(m));
  for (const TreePath& path : l.region_paths()) {
    l.unload_region(path);
    EXPECT_FALSE(l.region_loaded(path));
    EXPECT_EQ(l.state_hash(), hash);
  }
  EXPECT_EQ(l.stats().polygons, stats.polygons);
  EXPECT_EQ(l.stats().vertices, stats.vertices);
  EXPECT_EQ(l.stats().cells, stats.cells);
  EXPECT_EQ(l.stats().depth, stats.depth);
  for (int m = 0; m < 4; ++m) EXPECT_EQ(l.twice_area(m), areas[static_cast<std::size_t>(m)]);
  EXPECT_LT(l.stats().bytes, stats.bytes / 4);
  EXPECT_TRUE(l.check().ok());
}

TEST(Regions, AnEditOrAQueryThatReachesAStubIsRefusedAndChangesNothing) {
  Landscape l = edited(region_config(3), 100);
  const TreePath gone = l.regions_meeting({{100, 100}, {101, 101}}).front();
  l.unload_region(gone);
  const std::uint64_t hash = l.state_hash();
  try {
    l.carve(PolygonSet{pinned::blob({300, 300}, 400)});
    FAIL() << "carved";
  } catch (const RegionNotLoaded& e) {
    EXPECT_EQ(e.path, gone);
    EXPECT_TRUE(e.box.contains(Box64{{100, 100}, {101, 101}}));
  }
  EXPECT_EQ(l.state_hash(), hash);
  EXPECT_THROW((void)l.material_at({100, 100}), RegionNotLoaded);
  EXPECT_THROW((void)l.raycast({0, 50}, {4000, 50}), RegionNotLoaded);
  EXPECT_THROW(l.polygons_in({{0, 0}, {200, 200}}, [](const PolygonView&) { return true; }),
               RegionNotLoaded);
  EXPECT_THROW((void)l.overlaps(Box64{{0, 0}, {200, 200}}), RegionNotLoaded);
  std::ostringstream save;
  EXPECT_THROW(l.save(save), RegionNotLoaded);
  // Elsewhere everything works.
  EXPECT_NO_THROW(l.carve(PolygonSet{pinned::blob({3000, 3000}, 100)}));
  EXPECT_NO_THROW((void)l.material_at({3000, 3000}));
  EXPECT_TRUE(l.check().ok());
}

// Every polygon of the world with a bit of `pick` (by its index mod 64) set, named as remove takes
// them, and their rings.
std::vector<PolygonView> picked(const Landscape& l, std::uint64_t pick) {
  std::vector<PolygonView> out;
  std::uint64_t k = 0;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    if ((pick >> (k++ % 64)) & 1u) out.push_back(v);
    return true;
  });
  return out;
}

std::vector<PolygonRef> refs_of(const std::vector<PolygonView>& views) {
  std::vector<PolygonRef> out;
  for (const PolygonView& v : views) out.push_back({v.id, v.cell});
  return out;
}

// Landscape::remove (what the game driver detaches debris with) on a world with regions: the
// carve of the polygons' own region, region by region with their own ids, and a name in an
// unloaded region refused, or left out under kSkip, as an edit treats a stub. Landscape::cell
// refuses a box in an unloaded region as the queries do.
TEST(Regions, RemoveIsTheCarveOfItsPolygonsAndStopsAtAStub) {
  Landscape l = edited(region_config(3), 150);
  const std::vector<PolygonView> views = picked(l, 0x9249249249249249u);  // every third
  PolygonSet rings;
  for (const PolygonView& v : views) rings.push_back(*v.polygon);
  ASSERT_GT(l.regions_meeting(*bounding_box(rings)).size(), 20u);
  Landscape carved = l;
  const ChangeSet by_carve = carved.carve(ValidSet(rings));
  Landscape removed = l;
  const ChangeSet by_remove = removed.remove(refs_of(views));
  EXPECT_EQ(removed.state_hash(), carved.state_hash());
  EXPECT_EQ(by_remove.removed, by_carve.removed);
  EXPECT_TRUE(removed.check().ok());

  const TreePath gone = l.regions_meeting({{100, 100}, {101, 101}}).front();
  Landscape partial = l;
  partial.unload_region(gone);
  const std::uint64_t hash = partial.state_hash();
  EXPECT_THROW(partial.remove(refs_of(views)), RegionNotLoaded);
  EXPECT_EQ(partial.state_hash(), hash);
  const Box64 stub_box = partial.node_digest(gone)->box;
  EXPECT_THROW((void)partial.cell(stub_box), RegionNotLoaded);
  // Under kSkip the names in the stub are left out: every other region ends as the carve left it.
  std::vector<PolygonView> elsewhere;
  for (const PolygonView& v : views)
    if (!stub_box.contains(v.cell)) elsewhere.push_back(v);
  ASSERT_LT(elsewhere.size(), views.size());
  partial.set_unloaded_policy(UnloadedRegions::kSkip);
  partial.remove(refs_of(views));
  for (const TreePath& path : l.region_paths()) {
    if (path == gone) continue;
    EXPECT_EQ(partial.node_digest(path)->hash, carved.node_digest(path)->hash);
  }
  EXPECT_EQ(partial.node_digest(gone)->hash, l.node_digest(gone)->hash);
}

TEST(Regions, ARegionSavedUnloadedAndLoadedIsTheSameRegion) {
  Landscape l = edited(region_config(3));
  const Landscape before = l;
  for (const TreePath& path : l.region_paths()) {
    const std::string record = record_of(l, path);
    l.unload_region(path);
    load_record(l, record);
    EXPECT_TRUE(l.region_loaded(path));
  }
  EXPECT_EQ(l.state_hash(), before.state_hash());
  EXPECT_EQ(l.region_summary({1, 2, 3}), before.region_summary({1, 2, 3}));
  std::ostringstream a, b;
  l.save(a);
  before.save(b);
  EXPECT_EQ(a.str(), b.str());
  EXPECT_TRUE(l.check().ok());
}

TEST(Regions, ARecordOfAnotherWorldOrVersionOrDamagedIsRefused) {
  Landscape l = edited(region_config(3));
  const TreePath path{0, 1, 2};
  const std::string record = record_of(l, path);
  l.unload_region(path);
  const std::uint64_t hash = l.state_hash();
  const auto refused = [&](const std::string& bytes) {
    EXPECT_THROW(load_record(l, bytes), LoadError);
    EXPECT_FALSE(l.region_loaded(path));
    EXPECT_EQ(l.state_hash(), hash);
  };
  std::string damaged = record;
  damaged[damaged.size() / 2] ^= 4;
  refused(damaged);
  refused(record.substr(0, record.size() - 9));
  // Another version of the region: the stub's hash is not this record's.
  Landscape other = edited(region_config(3));
  other.carve(PolygonSet{pinned::blob(other.node_digest(path)->box.min, 300)});
  refused(record_of(other, path));
  // Another world.
  refused(record_of(edited(region_config(3, false)), path));
  // A summary without the region.
  std::ostringstream summary;
  l.save_region_summary(path, summary);
  refused(summary.str());
  // A record for a region that is loaded already.
  load_record(l, record);
  EXPECT_THROW(load_record(l, record), LoadError);
}

TEST(Regions, AWorldOfStubsFromSummariesLoadsToTheSameWorld) {
  const Landscape l = edited(region_config(3));
  std::vector<RegionSummary> summaries;
  for (const TreePath& path : l.region_paths()) {
    std::ostringstream out;
    l.save_region_summary(path, out);
    std::istringstream in(out.str());
    summaries.push_back(Landscape::read_region_summary(in));
  }
  Landscape stubs = Landscape::from_regions(l.world(), l.config(), l.next_id(), summaries);
  EXPECT_EQ(stubs.state_hash(), l.state_hash());
  EXPECT_EQ(stubs.twice_area(2), l.twice_area(2));
  for (const TreePath& path : l.region_paths()) load_record(stubs, record_of(l, path));
  EXPECT_TRUE(stubs.check().ok());
  EXPECT_EQ(stubs.state_hash(), l.state_hash());
  std::vector<RegionSummary> missing(summaries.begin() + 1, summaries.end());
  EXPECT_THROW(Landscape::from_regions(l.world(), l.config(), 1, missing), LoadError);
  missing.push_back(summaries[5]);
  missing.push_back(summaries[5]);
  EXPECT_THROW(Landscape::from_regions(l.world(), l.config(), 1, missing), LoadError);
  EXPECT_THROW(Landscape::from_regions(l.world(), LandscapeConfig{}, 1, summaries), InvalidConfig);
}

TEST(Regions, ASaveFileKeepsTheRegionsAndTheirCounters) {
  const Landscape l = edited(region_config(4));
  std::stringstream bytes;
  l.save(bytes);
  const Landscape back = Landscape::load(bytes);
  EXPECT_EQ(back.state_hash(), l.state_hash());
  EXPECT_EQ(back.config().region_depth, 4);
  EXPECT_TRUE(back.config().region_ids);
  EXPECT_TRUE(back.check().ok());
  std::ostringstream plain;
  Landscape({{0, 0}, {4096, 4096}}, 1).save(plain);
  EXPECT_EQ(plain.str()[8], 1);  // a world without regions is still a version 1 file
}

// Item 6: regions edited apart. Two owners each hold half the regions (the others as stubs,
// skipped by edits) and apply every edit, edits across region lines included; each half is the
// one-process world's, and the halves together are that world, hash for hash.
TEST(Regions, TwoOwnersOfDisjointRegionsTogetherMakeTheOneProcessWorld) {
  const LandscapeConfig config = region_config(3);
  Landscape single({{0, 0}, {4096, 4096}}, 1, config);
  Landscape even = single, odd = single;
  const std::vector<TreePath> paths = single.region_paths();
  for (std::size_t i = 0; i < paths.size(); ++i) (i % 2 ? even : odd).unload_region(paths[i]);
  even.set_unloaded_policy(UnloadedRegions::kSkip);
  odd.set_unloaded_policy(UnloadedRegions::kSkip);
  std::uint64_t seed = 9;
  for (int i = 0; i < 250; ++i) {
    const Point64 c{static_cast<std::int64_t>(pinned::splitmix64(seed) % 4096),
                    static_cast<std::int64_t>(pinned::splitmix64(seed) % 4096)};
    // Radius up to 700: many edits cross region lines. Every tenth is a comb across the whole
    // world, cut to the cells of each region apart.
    const std::int64_t r = 40 + static_cast<std::int64_t>(pinned::splitmix64(seed) % 660);
    const ValidSet shape(
        PolygonSet{i % 10 == 5 ? comb(c.y % 3900, 30 + r % 60) : pinned::blob(c, r)});
    const Edit e = i % 4 == 0 ? Edit::fill(shape, 2) : Edit::carve(shape);
    apply_edit(single, e);
    apply_edit(even, e);
    apply_edit(odd, e);
  }
  Landscape together = single;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const Landscape& owner = i % 2 ? odd : even;
    EXPECT_EQ(owner.node_digest(paths[i])->hash, single.node_digest(paths[i])->hash) << i;
    together.unload_region(paths[i]);
    load_record(together, record_of(owner, paths[i]));
  }
  EXPECT_EQ(together.state_hash(), single.state_hash());
  EXPECT_TRUE(together.check().ok());
}

// A client holding a region as a stub brings it in with a PATCH at the region's path; a repair
// below a region's node carries the region's id counter.
TEST(Regions, APatchBringsInARegionOrRepairsBelowOne) {
  const Landscape server = edited(region_config(3));
  Landscape client = server;
  const TreePath region{2, 1, 0};
  client.unload_region(region);
  client.set_unloaded_policy(UnloadedRegions::kSkip);
  client.apply_delta(patch_delta(server, 1, {region}), {.base = false});
  EXPECT_TRUE(client.region_loaded(region));
  EXPECT_EQ(client.state_hash(), server.state_hash());
  // A stray edit inside one region, repaired below its node.
  Landscape diverged = server;
  const Box64 box = server.node_digest(region)->box;
  diverged.fill(PolygonSet{pinned::blob({box.min.x + 100, box.min.y + 100}, 60)}, 7);
  DivergenceSearch search(std::vector<TreePath>{region});
  while (!search.done()) {
    std::vector<std::optional<NodeDigest>> answers;
    for (const TreePath& p : search.questions()) answers.push_back(server.node_digest(p));
    search.answer(diverged, answers);
  }
  ASSERT_FALSE(search.differing().empty());
  const Delta patch = patch_delta(server, 2, search.differing());
  diverged.apply_delta(decode_delta(encode_delta(patch)), {.base = false});
  EXPECT_EQ(diverged.state_hash(), server.state_hash());
  EXPECT_TRUE(diverged.check().ok());
}

}  // namespace
}  // namespace edgeland
