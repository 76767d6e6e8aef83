// The landscape (landscape.hpp): edits, ids and change sets, splits and merges, the strong
// guarantee, save/load, and the basic queries on hand-made worlds whose answers are known.
#include "edgeland/spatial/landscape.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>

#include "check.hpp"  // spatial/src: the error checked mode throws
#include "edgeland/spatial/tree_boxes.hpp"
#include "edit_log.hpp"
#include "polygon_set_helpers.hpp"
#include "state_of.hpp"

namespace edgeland::test {
namespace {

Polygon box_polygon(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A regular-ish n-gon of radius r around c (integer vertices, counter-clockwise).
Polygon ngon(Point64 c, std::int64_t r, int n) {
  // Integer points on a circle by a rotation-free table: a fixed 32-step turn of (r, 0) with
  // cos/sin tabled as fractions of 1000 (exactness is not needed, only validity).
  static const int cs[32][2] = {
      {1000, 0},    {981, 195},   {924, 383},   {831, 556},   {707, 707},   {556, 831},
      {383, 924},   {195, 981},   {0, 1000},    {-195, 981},  {-383, 924},  {-556, 831},
      {-707, 707},  {-831, 556},  {-924, 383},  {-981, 195},  {-1000, 0},   {-981, -195},
      {-924, -383}, {-831, -556}, {-707, -707}, {-556, -831}, {-383, -924}, {-195, -981},
      {0, -1000},   {195, -981},  {383, -924},  {556, -831},  {707, -707},  {831, -556},
      {924, -383},  {981, -195}};
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const int k = i * 32 / n;
    p.push_back({c.x + r * cs[k][0] / 1000, c.y + r * cs[k][1] / 1000});
  }
  return p;
}

Landscape checked_world(const Box64& w, Material fill = kEmpty, LandscapeConfig config = {}) {
  Landscape l(w, fill, config);
  l.set_checked(true);
  return l;
}

TEST(Landscape, StartsEmptyOrFilled) {
  const Landscape empty({{0, 0}, {100, 50}});
  EXPECT_EQ(empty.stats().polygons, 0u);
  EXPECT_EQ(empty.twice_area(kEmpty), 2 * 100 * 50);
  const Landscape rock({{0, 0}, {100, 50}}, 3);
  EXPECT_EQ(rock.twice_area(3), 2 * 100 * 50);
  EXPECT_EQ(rock.twice_area(kEmpty), 0);
  EXPECT_EQ(rock.material_at({0, 0}), 3);
  EXPECT_EQ(rock.material_at({99, 49}), 3);
  EXPECT_EQ(rock.material_at({100, 10}), kEmpty);  // the max side belongs to the outside
  EXPECT_TRUE(rock.check().ok());
}

// The setting an unusable world or configuration breaks, with the box and configuration given.
InvalidConfig config_error(const Box64& world, const LandscapeConfig& c = {}) {
  try {
    Landscape l(world, kEmpty, c);
  } catch (const InvalidConfig& e) {
    return e;
  }
  ADD_FAILURE() << "no InvalidConfig";
  return InvalidConfig(InvalidConfig::Setting::kTree, world, c);
}

TEST(Landscape, RejectsUnusableWorldsAndConfigs) {
  using Setting = InvalidConfig::Setting;
  const InvalidConfig flat = config_error({{0, 0}, {0, 10}});
  EXPECT_EQ(flat.setting, Setting::kWorldEmpty);
  EXPECT_EQ(flat.world, (Box64{{0, 0}, {0, 10}}));
  EXPECT_EQ(std::string(flat.what()), "world box (0 0, 0 10) without positive width and height");
  const InvalidConfig inverted = config_error({{10, 0}, {0, 10}});
  EXPECT_EQ(inverted.setting, Setting::kWorldEmpty);
  EXPECT_EQ(inverted.world.min.x, 10);
  const InvalidConfig far = config_error({{0, 0}, {kCoordBound + 1, 10}});
  EXPECT_EQ(far.setting, Setting::kWorldOutOfRange);
  EXPECT_EQ(far.world.max.x, kCoordBound + 1);
  LandscapeConfig c;
  c.merge_below = c.edge_cap;
  const InvalidConfig merge = config_error({{0, 0}, {10, 10}}, c);
  EXPECT_EQ(merge.setting, Setting::kMergeBelow);
  EXPECT_EQ(merge.config.merge_below, c.edge_cap);
  EXPECT_EQ(std::string(merge.what()), "merge_below " + std::to_string(c.edge_cap) +
                                           " not below edge_cap " + std::to_string(c.edge_cap));
}

TEST(Landscape, FillCarveAndReplaceChangeExactAreas) {
  Landscape l = checked_world({{0, 0}, {1000, 1000}});
  const ChangeSet filled = l.fill(PolygonSet{box_polygon(100, 100, 300, 200)}, 1);
  EXPECT_EQ(l.twice_area(1), 2 * 200 * 100);
  ASSERT_EQ(filled.added.size(), 1u);
  EXPECT_TRUE(filled.removed.empty());
  EXPECT_EQ(filled.twice_area_delta.size(), 2u);  // material 0 down, material 1 up
  l.fill(PolygonSet{box_polygon(200, 150, 400, 250)}, 2);
  EXPECT_EQ(l.twice_area(1), 2 * (200 * 100 - 100 * 50));
  EXPECT_EQ(l.twice_area(2), 2 * 200 * 100);
  l.replace(PolygonSet{box_polygon(0, 0, 250, 1000)}, 2, 5);
  EXPECT_EQ(l.twice_area(5), 2 * 50 * 100);
  EXPECT_EQ(l.material_at({220, 180}), 5);
  EXPECT_EQ(l.material_at({260, 180}), 2);
  l.fill_empty(PolygonSet{box_polygon(0, 0, 1000, 1000)}, 7);
  EXPECT_EQ(l.twice_area(kEmpty), 0);
  EXPECT_EQ(l.material_at({220, 180}), 5);
  l.carve(PolygonSet{box_polygon(0, 0, 1000, 500)});
  EXPECT_EQ(l.twice_area(kEmpty), 2 * 1000 * 500);
  EXPECT_EQ(l.material_at({220, 180}), kEmpty);
  EXPECT_EQ(l.material_at({500, 700}), 7);
  EXPECT_TRUE(l.check().ok()) << l.check().problems.front();
}

TEST(Landscape, UnchangedPolygonsKeepTheirIds) {
  Landscape l = checked_world({{0, 0}, {1000, 1000}});
  const ChangeSet a = l.fill(PolygonSet{box_polygon(100, 100, 200, 200)}, 1);
  const ChangeSet b = l.fill(PolygonSet{box_polygon(600, 600, 700, 700)}, 1);
  ASSERT_EQ(a.added.size(), 1u);
  ASSERT_EQ(b.added.size(), 1u);
  // Carving the second square leaves the first (same cell) with its id.
  const ChangeSet c = l.carve(PolygonSet{box_polygon(650, 650, 750, 750)});
  EXPECT_EQ(c.removed, std::vector<PolygonId>{b.added[0].id});
  bool first_still_there = false;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    first_still_there = first_still_there || v.id == a.added[0].id;
    return true;
  });
  EXPECT_TRUE(first_still_there);
}

TEST(Landscape, ShapesPastTheWorldAreCutToIt) {
  Landscape l = checked_world({{0, 0}, {100, 100}});
  l.fill(PolygonSet{box_polygon(-50, -50, 50, 50)}, 4);
  EXPECT_EQ(l.twice_area(4), 2 * 50 * 50);
  l.fill(PolygonSet{box_polygon(200, 200, 300, 300)}, 4);  // wholly outside: nothing
  EXPECT_EQ(l.twice_area(4), 2 * 50 * 50);
}

TEST(Landscape, SplitsCrowdedCellsAndMergesThemBack) {
  LandscapeConfig config;
  config.edge_cap = 64;
  config.merge_below = 24;
  Landscape l = checked_world({{0, 0}, {4096, 4096}}, 1, config);
  std::vector<Polygon> holes;
  for (int i = 0; i < 12; ++i) holes.push_back(ngon({300 + 300 * i, 2000}, 90, 32));
  for (const Polygon& h : holes) l.carve(PolygonSet{h});
  EXPECT_GT(l.stats().cells, 1u);
  EXPECT_TRUE(l.check().ok()) << l.check().problems.front();
  // The cells tile the world: their areas add up to it, and they hold every polygon.
  Int128 cell_area = 0;
  std::size_t polygons = 0;
  l.cells_in(l.world(), [&](const CellView& c) {
    cell_area += Int128(c.box.max.x - c.box.min.x) * (c.box.max.y - c.box.min.y);
    polygons += c.polygons;
    return true;
  });
  EXPECT_EQ(cell_area, Int128(4096) * 4096);
  EXPECT_EQ(polygons, l.stats().polygons);
  // Fill everything again: the cells shrink to one rectangle each and merge back to one.
  l.fill(PolygonSet{box_polygon(0, 0, 4096, 4096)}, 1);
  EXPECT_EQ(l.stats().cells, 1u);
  EXPECT_EQ(l.stats().polygons, 1u);
  EXPECT_EQ(l.twice_area(1), Int128(2) * 4096 * 4096);
  EXPECT_TRUE(l.check().ok()) << l.check().problems.front();
}

TEST(Landscape, AFailedEditChangesNothing) {
  Landscape l = checked_world({{0, 0}, {1000, 1000}}, 2);
  l.carve(PolygonSet{ngon({500, 500}, 100, 32)});
  const std::uint64_t before = l.state_hash();
  const PolygonSet bow_tie{{{0, 0}, {10, 10}, {10, 0}, {0, 10}}};
  EXPECT_THROW(l.carve(bow_tie), InvalidInput);
  const PolygonSet far{box_polygon(0, 0, kCoordBound + 5, 10)};
  EXPECT_THROW(l.fill(far, 3), CoordinateOutOfRange);
  EXPECT_EQ(l.state_hash(), before);
  Landscape limited({{0, 0}, {1000, 1000}}, 2, {}, LandscapeLimits{.max_vertices = 30});
  const std::uint64_t lb = limited.state_hash();
  EXPECT_THROW(limited.carve(PolygonSet{ngon({500, 500}, 100, 32)}), LimitExceeded);
  EXPECT_EQ(limited.state_hash(), lb);
}

TEST(Landscape, CopiesAreSnapshots) {
  Landscape l = checked_world({{0, 0}, {1000, 1000}}, 1);
  const Landscape snapshot = l;
  const std::uint64_t h = l.state_hash();
  l.carve(PolygonSet{ngon({300, 300}, 80, 32)});
  EXPECT_NE(l.state_hash(), h);
  EXPECT_EQ(snapshot.state_hash(), h);
  EXPECT_EQ(snapshot.twice_area(1), 2 * 1000 * 1000);
  l = snapshot;
  EXPECT_EQ(l.state_hash(), h);
}

TEST(Landscape, SavesAndLoadsTheSameState) {
  Landscape l = checked_world({{-5000, -5000}, {5000, 5000}}, 1);
  for (int i = 0; i < 20; ++i) l.carve(PolygonSet{ngon({-4000 + 400 * i, 37 * i}, 150, 32)});
  l.fill(PolygonSet{ngon({0, 0}, 700, 32)}, 9);
  std::stringstream file;
  l.save(file);
  const Landscape back = Landscape::load(file);
  EXPECT_EQ(back.state_hash(), l.state_hash());
  EXPECT_EQ(back.twice_area(9), l.twice_area(9));
  EXPECT_TRUE(back.check().ok());
}

TEST(Landscape, LoadRejectsDamagedFiles) {
  Landscape l({{0, 0}, {1000, 1000}}, 1);
  l.carve(PolygonSet{ngon({500, 500}, 100, 32)});
  std::stringstream file;
  l.save(file);
  const std::string bytes = file.str();
  for (std::size_t cut : {std::size_t{0}, std::size_t{5}, bytes.size() / 2, bytes.size() - 1}) {
    std::stringstream truncated(bytes.substr(0, cut));
    EXPECT_THROW(Landscape::load(truncated), LoadError) << cut;
  }
  for (std::size_t at = 0; at < bytes.size(); at += 7) {
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x20);
    std::stringstream in(damaged);
    EXPECT_THROW(Landscape::load(in), LoadError) << at;
  }
}

TEST(Landscape, RaycastHitsTheFirstSurfaceFromOutside) {
  Landscape l = checked_world({{0, 0}, {1000, 1000}});
  l.fill(PolygonSet{box_polygon(100, 100, 300, 200)}, 1);
  l.fill(PolygonSet{box_polygon(300, 100, 500, 200)}, 2);
  const auto hit = l.raycast({0, 150}, {1000, 150});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->rounded, (Point64{100, 150}));
  EXPECT_EQ(hit->after, 1);
  EXPECT_EQ(hit->before, kEmpty);
  EXPECT_EQ(hit->normal.x < 0, true);
  // From inside material 1 the next hit is material 2, at the shared boundary.
  const auto inner = l.raycast({150, 150}, {1000, 150});
  ASSERT_TRUE(inner.has_value());
  EXPECT_EQ(inner->rounded, (Point64{300, 150}));
  EXPECT_EQ(inner->after, 2);
  // From inside 2 going right: out into empty space only: no hit.
  EXPECT_FALSE(l.raycast({400, 150}, {1000, 150}).has_value());
  // All crossings: 0 -> 1 -> 2 -> 0.
  const auto all = l.crossings({0, 150}, {1000, 150});
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[2].after, kEmpty);
  EXPECT_EQ(all[2].rounded, (Point64{500, 150}));
}

TEST(Landscape, OverlapsFindsMaterialsUnderABox) {
  Landscape l = checked_world({{0, 0}, {1000, 1000}});
  l.fill(PolygonSet{box_polygon(100, 100, 300, 200)}, 1);
  l.fill(PolygonSet{box_polygon(300, 100, 500, 200)}, 2);
  EXPECT_EQ(l.overlaps(Box64{{290, 150}, {310, 160}}), (std::vector<Material>{1, 2}));
  EXPECT_EQ(l.overlaps(Box64{{300, 150}, {310, 160}}), (std::vector<Material>{2}));
  EXPECT_TRUE(l.overlaps(Box64{{0, 0}, {100, 100}}).empty());  // touches a corner only
  EXPECT_EQ(l.overlaps(ValidSet(PolygonSet{{{250, 90}, {350, 90}, {300, 150}}})),
            (std::vector<Material>{1, 2}));
}

// landscape.hpp: the box queries take an inverted box (min > max) as the empty set it is: it
// overlaps no material and meets no polygon or cell, though the span between its corners
// (x 200..400 here, across both squares and the world's cell) would.
TEST(Landscape, AnInvertedBoxMeetsNothing) {
  Landscape l = checked_world({{0, 0}, {1000, 1000}});
  l.fill(PolygonSet{box_polygon(100, 100, 300, 200)}, 1);
  l.fill(PolygonSet{box_polygon(300, 100, 500, 200)}, 2);
  const std::uint64_t before = l.state_hash();
  for (const Box64& box : {Box64{{400, 150}, {200, 160}}, Box64{{200, 160}, {400, 150}}}) {
    EXPECT_TRUE(l.overlaps(box).empty());
    std::size_t met = 0;
    l.polygons_in(box, [&](const PolygonView&) {
      ++met;
      return true;
    });
    l.cells_in(box, [&](const CellView&) {
      ++met;
      return true;
    });
    EXPECT_EQ(met, 0u);
  }
  EXPECT_EQ(l.state_hash(), before);
}

// landscape.hpp: overlaps(Box64) computes with the box's corners, so a corner beyond the bound
// is a CoordinateOutOfRange (operand kQuery) naming it (vertex 0: the box's min), as for every
// query. (This box, spanning the int64 range, once reached the exact tests and overflowed: an
// abort in the checked build.)
TEST(Landscape, OverlapsRefusesABoxCornerBeyondTheBound) {
  Landscape l = checked_world({{0, 0}, {1000, 1000}});
  l.fill(PolygonSet{box_polygon(100, 100, 300, 200)}, 1);
  const Point64 far{std::numeric_limits<std::int64_t>::min(), 150};
  try {
    const std::vector<Material> got =
        l.overlaps(Box64{far, {std::numeric_limits<std::int64_t>::max(), 160}});
    FAIL() << "answered " << got.size() << " materials";
  } catch (const CoordinateOutOfRange& e) {
    EXPECT_EQ(e.operand, Operand::kQuery);
    EXPECT_EQ(e.where, far);
    EXPECT_EQ(e.vertex, 0u);
  }
}

// Point 16 of issue 27: grid_depth was silently capped by min_cell_size (a 100 x 100 world with
// min_cell_size 16 and grid_depth 5 built a grid of depth 3). Now the deepest grid the world
// allows is max_grid_depth, and a deeper grid_depth is refused with a typed error naming it.
TEST(LandscapeLimits, AGridDeeperThanItsCellsIsRefused) {
  const Box64 world{{0, 0}, {100, 100}};  // 100 -> 50 -> 25 -> 12 or 13: no side above 16
  LandscapeConfig grid;
  grid.grid_depth = 3;
  EXPECT_EQ(max_grid_depth(world, grid), 3);
  const Landscape full(world, 1, grid);
  EXPECT_EQ(full.stats().cells, 64u);
  EXPECT_EQ(full.stats().depth, 3u);
  grid.grid_depth = 4;
  const InvalidConfig deep = config_error(world, grid);
  EXPECT_EQ(deep.setting, InvalidConfig::Setting::kGridDepthBeyondCells);
  EXPECT_STREQ(deep.what(),
               "grid_depth 4 deeper than min_cell_size 16 lets the world box (0 0, 100 100) "
               "split (at most 3)");
  // A kd-tree halves one side per level: twice the levels of the quadtree, and a long thin
  // world splits only along its long side once the short one is down to min_cell_size.
  grid.tree = TreeKind::kKdTree;
  EXPECT_EQ(max_grid_depth(world, grid), 6);
  EXPECT_EQ(max_grid_depth({{0, 0}, {1024, 16}}, grid), 6);  // 1024 -> 16 along x only
  grid.tree = TreeKind::kQuadtree;
  EXPECT_EQ(max_grid_depth({{0, 0}, {1024, 16}}, grid), 6);
  grid.min_cell_size = 1;
  EXPECT_EQ(max_grid_depth({{0, 0}, {1, 1}}, grid), 0);
  EXPECT_EQ(max_grid_depth({{0, 0}, {1024, 1024}}, grid), 10);
}

}  // namespace
}  // namespace edgeland::test

namespace edgeland::test {
namespace {

TEST(LandscapeLimits, ASplitThatWouldPassTheVertexLimitStopsEarlyAndChangesNothing) {
  LandscapeConfig config;
  config.edge_cap = 32;
  config.merge_below = 10;
  Landscape l({{0, 0}, {1 << 20, 1 << 20}}, 1, config, LandscapeLimits{.max_vertices = 200});
  const std::uint64_t before = l.state_hash();
  // A comb of 40 teeth: far more edges than a cell may hold, so cells split, each split adding
  // vertices along its cut lines, until the limit stops it.
  const std::int64_t step = 12000, tooth = 4000, base = 1000, top = 1 << 18;
  const int teeth = 40;
  Polygon comb{{0, 0}, {teeth * step, 0}, {teeth * step, base}};
  for (int i = teeth - 1; i >= 0; --i) {
    const std::int64_t x = i * step + 4000;
    comb.insert(comb.end(), {{x + tooth, base}, {x + tooth, top}, {x, top}, {x, base}});
  }
  comb.push_back({0, base});
  try {
    l.carve(ValidSet(PolygonSet{comb}));
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit, LimitExceeded::Limit::kVertices);
    EXPECT_GT(e.requested, e.maximum);
  } catch (const InvalidInput& e) {
    FAIL() << "the comb is not valid: " << e.what();
  }
  EXPECT_EQ(l.state_hash(), before);
}

TEST(LandscapeLimits, ConfigurationsThatCannotWorkAreRefused) {
  LandscapeConfig small_cap;
  small_cap.edge_cap = 16;
  small_cap.merge_below = 4;
  EXPECT_EQ(config_error({{0, 0}, {100, 100}}, small_cap).setting,
            InvalidConfig::Setting::kEdgeCap);
  LandscapeConfig deep_grid;
  deep_grid.grid_depth = 11;
  EXPECT_EQ(config_error({{0, 0}, {100, 100}}, deep_grid).setting,
            InvalidConfig::Setting::kGridDepth);
  LandscapeConfig no_cells;
  no_cells.min_cell_size = 0;
  EXPECT_EQ(config_error({{0, 0}, {100, 100}}, no_cells).setting,
            InvalidConfig::Setting::kMinCellSize);
  LandscapeConfig unknown_tree;
  unknown_tree.tree = static_cast<TreeKind>(7);
  EXPECT_EQ(config_error({{0, 0}, {100, 100}}, unknown_tree).setting,
            InvalidConfig::Setting::kTree);
}

}  // namespace
}  // namespace edgeland::test

namespace edgeland::test {
namespace {

// What a checked-mode failure carries (check.hpp internal_error, thrown by every failed check):
// the world before the edit as a save file, and a log replaying to it followed by the edit.
TEST(LandscapeInternalError, CarriesTheStateAndAReplayableLog) {
  Landscape recorded({{0, 0}, {1000, 1000}}, 1);
  recorded.start_log();
  recorded.carve(PolygonSet{ngon({300, 300}, 80, 32)});
  recorded.fill(PolygonSet{ngon({600, 600}, 120, 32)}, 2);
  const std::string edit = "carve MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)))\n";
  detail::LandscapeState recorded_state = state_of(recorded);
  recorded_state.logging = true;
  detail::append_log(recorded_state, recorded.log());
  const LandscapeInternalError e = detail::internal_error(recorded_state, "a test", edit);
  std::istringstream state(e.state);
  EXPECT_EQ(Landscape::load(state).state_hash(), recorded.state_hash());
  EXPECT_EQ(e.log, recorded.log() + edit);
  EXPECT_EQ(e.log.rfind("world 0 0 1000 1000 1\n", 0), 0u);
  EXPECT_NE(std::string(e.what()).find("a test"), std::string::npos);
  // Not recording: the world and one fill per material, then the edit.
  Landscape quiet({{0, 0}, {1000, 1000}}, 1);
  quiet.carve(PolygonSet{ngon({300, 300}, 80, 32)});
  const LandscapeInternalError q = detail::internal_error(state_of(quiet), "a test", edit);
  EXPECT_EQ(q.log.rfind("world 0 0 1000 1000\nfill 1 MULTIPOLYGON", 0), 0u);
  EXPECT_EQ(q.log.substr(q.log.size() - edit.size()), edit);
}

}  // namespace
}  // namespace edgeland::test
