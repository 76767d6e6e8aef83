// The landscape's configuration, limits and errors (spatial/README.md, "The model"; errors.hpp):
// every rule of a configuration refused with its own setting and a message naming the value,
// the tree's cut rules on boxes whose sides differ, and each resource limit stopping the
// operation it bounds with the world unchanged. Values are worked out from the headers'
// contracts.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

#include "edgeland/spatial/landscape.hpp"
#include "edgeland/spatial/tree_boxes.hpp"

namespace edgeland::test {
namespace {

using Setting = InvalidConfig::Setting;

Polygon square(std::int64_t x, std::int64_t y, std::int64_t side) {
  return {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
}

// The setting a world and configuration are refused for, and the message.
struct Refusal {
  Setting setting;
  std::string what;
};
Refusal refusal(const Box64& world, const LandscapeConfig& config) {
  try {
    Landscape l(world, kEmpty, config);
  } catch (const InvalidConfig& e) {
    EXPECT_EQ(e.world, world);
    return {e.setting, e.what()};
  }
  ADD_FAILURE() << "accepted";
  return {};
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(LandscapeConfigRules, EachRuleIsRefusedWithItsSetting) {
  const Box64 w{{0, 0}, {1024, 1024}};
  Refusal r = refusal({{0, 0}, {kCoordBound + 1, 10}}, {});
  EXPECT_EQ(r.setting, Setting::kWorldOutOfRange);
  EXPECT_TRUE(contains(r.what, "world box (0 0, 2147483648 10) beyond the coordinate bound"));
  EXPECT_EQ(refusal({{-kCoordBound - 1, 0}, {10, 10}}, {}).setting, Setting::kWorldOutOfRange);
  r = refusal({{0, 0}, {10, 0}}, {});  // no height
  EXPECT_EQ(r.setting, Setting::kWorldEmpty);
  EXPECT_TRUE(contains(r.what, "(0 0, 10 0) without positive width and height"));
  EXPECT_EQ(refusal({{10, 0}, {0, 10}}, {}).setting, Setting::kWorldEmpty);  // inverted
  r = refusal(w, {.edge_cap = 31, .merge_below = 8});
  EXPECT_EQ(r.setting, Setting::kEdgeCap);
  EXPECT_TRUE(contains(r.what, "edge_cap 31 below 32"));
  r = refusal(w, {.edge_cap = 32, .merge_below = 32});
  EXPECT_EQ(r.setting, Setting::kMergeBelow);
  EXPECT_TRUE(contains(r.what, "merge_below 32 not below edge_cap 32"));
  r = refusal(w, {.min_cell_size = 0});
  EXPECT_EQ(r.setting, Setting::kMinCellSize);
  EXPECT_TRUE(contains(r.what, "min_cell_size 0 below 1"));
  r = refusal(w, {.grid_depth = -2});
  EXPECT_EQ(r.setting, Setting::kGridDepth);
  EXPECT_TRUE(contains(r.what, "grid_depth -2 outside -1..10"));
  EXPECT_EQ(refusal(w, {.grid_depth = 11}).setting, Setting::kGridDepth);
  r = refusal(w, {.tree = static_cast<TreeKind>(7)});
  EXPECT_EQ(r.setting, Setting::kTree);
  EXPECT_TRUE(contains(r.what, "unknown tree kind 7"));
  // The limits of each rule are accepted.
  EXPECT_NO_THROW(Landscape(w, kEmpty, {.edge_cap = 32, .merge_below = 31, .min_cell_size = 1}));
  EXPECT_NO_THROW(Landscape({{-kCoordBound, -kCoordBound}, {kCoordBound, kCoordBound}}));
  EXPECT_NO_THROW(Landscape({{0, 0}, {64, 64}}, kEmpty, {.min_cell_size = 32, .grid_depth = 1}));
  EXPECT_EQ(refusal({{0, 0}, {64, 64}}, {.min_cell_size = 32, .grid_depth = 2}).setting,
            Setting::kGridDepthBeyondCells);
}

// A kd-tree cuts the longer side (x on ties); a side at most min_cell_size is never cut, in a
// quadtree too; a box with neither side cuttable has no children.
TEST(TreeBoxes, TheLongerSideIsCutAndShortOnesNever) {
  const LandscapeConfig kd{.tree = TreeKind::kKdTree, .min_cell_size = 4};
  EXPECT_EQ(child_boxes({{0, 0}, {10, 20}}, kd),
            (std::vector<Box64>{{{0, 0}, {10, 10}}, {{0, 10}, {10, 20}}}));
  EXPECT_EQ(child_boxes({{0, 0}, {20, 20}}, kd),
            (std::vector<Box64>{{{0, 0}, {10, 20}}, {{10, 0}, {20, 20}}}));
  EXPECT_EQ(child_boxes({{0, 0}, {20, 3}}, kd),
            (std::vector<Box64>{{{0, 0}, {10, 3}}, {{10, 0}, {20, 3}}}));
  const LandscapeConfig quad{.min_cell_size = 4};
  EXPECT_EQ(child_boxes({{0, 0}, {3, 20}}, quad),
            (std::vector<Box64>{{{0, 0}, {3, 10}}, {{0, 10}, {3, 20}}}));
  EXPECT_EQ(child_boxes({{0, 0}, {9, 9}}, quad).size(), 4u);
  EXPECT_EQ(child_boxes({{0, 0}, {9, 9}}, quad)[0], (Box64{{0, 0}, {4, 4}}));
  EXPECT_TRUE(child_boxes({{0, 0}, {4, 4}}, quad).empty());
}

// A kd-tree landscape over a wide world: a fill that splits its cells keeps every invariant,
// and the cells halve one side at a time, so each is at most twice as long as it is wide
// (the world's own 4:1 aside) and together they tile the world.
TEST(TreeBoxes, AKdTreeLandscapeSplitsItsLongerSides) {
  Landscape l({{0, 0}, {4096, 1024}}, kEmpty, {.tree = TreeKind::kKdTree, .edge_cap = 32});
  l.set_checked(true);
  Polygon zigzag;
  for (std::int64_t i = 0; i <= 200; ++i) zigzag.push_back({20 * i, i % 2 == 0 ? 100 : 140});
  zigzag.push_back({4000, 900});
  zigzag.push_back({0, 900});
  l.fill(PolygonSet{zigzag}, 1);
  EXPECT_TRUE(l.check().ok());
  EXPECT_GT(l.stats().cells, 4u);
  std::int64_t area = 0;
  l.cells_in(l.world(), [&](const CellView& c) {
    const std::int64_t w = c.box.max.x - c.box.min.x, h = c.box.max.y - c.box.min.y;
    area += w * h;
    EXPECT_TRUE(w == h || w == 2 * h || 2 * w == h || w == 4 * h) << w << " x " << h;
    return true;
  });
  EXPECT_EQ(area, 4096 * 1024);
}

// A grid goes as deep as min_cell_size lets its cells split, and no deeper: a deeper grid_depth
// is refused (InvalidConfig kGridDepthBeyondCells), not quietly cut short.
TEST(GridWorlds, AGridGoesAsDeepAsItsCellsMaySplit) {
  EXPECT_EQ(refusal({{0, 0}, {64, 64}}, {.min_cell_size = 16, .grid_depth = 3}).setting,
            Setting::kGridDepthBeyondCells);
  const Landscape l({{0, 0}, {64, 64}}, 1, {.min_cell_size = 16, .grid_depth = 2});
  EXPECT_EQ(l.stats().cells, 16u);  // 64 / 16 = 4 cells a side: depth 2
  EXPECT_EQ(l.stats().depth, 2u);
  EXPECT_TRUE(l.check().ok());
  EXPECT_EQ(l.twice_area(1), 2 * 64 * 64);
}

// --- limits -------------------------------------------------------------------------------------

TEST(LandscapeLimitsHold, AGridOverTheCellLimitIsRefused) {
  try {
    Landscape l({{0, 0}, {1024, 1024}}, 1, {.grid_depth = 2}, {.max_cells = 10});
    FAIL() << "16 cells made under a limit of 10";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit, LimitExceeded::Limit::kCells);
    EXPECT_EQ(e.maximum, 10u);
    EXPECT_EQ(e.requested, 11u);  // refused at the first cell past the limit
    EXPECT_EQ(std::string(e.what()), "cell limit exceeded: 11 > 10");
  }
  EXPECT_EQ(
      Landscape({{0, 0}, {1024, 1024}}, 1, {.grid_depth = 2}, {.max_cells = 16}).stats().cells,
      16u);
}

TEST(LandscapeLimitsHold, AShapeOverTheShapeVertexLimitIsRefused) {
  Landscape l({{0, 0}, {1024, 1024}}, 1, {}, {.max_shape_vertices = 3});
  const std::uint64_t before = l.state_hash();
  try {
    l.carve(PolygonSet{square(10, 10, 20)});
    FAIL() << "a 4-vertex shape under a limit of 3";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit, LimitExceeded::Limit::kShapeVertices);
    EXPECT_EQ(e.requested, 4u);
    EXPECT_EQ(std::string(e.what()), "shape vertex limit exceeded: 4 > 3");
  }
  EXPECT_EQ(l.state_hash(), before);
  EXPECT_NO_THROW(l.carve(PolygonSet{{{10, 10}, {30, 10}, {10, 30}}}));
}

// An edit whose splits would pass the cell limit stops as soon as they would, and changes
// nothing.
TEST(LandscapeLimitsHold, SplitsPastTheCellLimitAreRefused) {
  Landscape l({{0, 0}, {1024, 1024}}, kEmpty, {.edge_cap = 32, .merge_below = 8}, {.max_cells = 4});
  const std::uint64_t before = l.state_hash();
  // 200 one-unit teeth along y = 500: far over the cap in every cell they cross.
  Polygon comb;
  for (std::int64_t i = 0; i < 100; ++i) {
    comb.push_back({10 * i, 500});
    comb.push_back({10 * i + 5, 501});
  }
  comb.push_back({1000, 500});
  comb.push_back({1000, 900});
  comb.push_back({0, 900});
  try {
    l.fill(PolygonSet{comb}, 1);
    FAIL() << "the comb needs more than 4 cells";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit, LimitExceeded::Limit::kCells);
    EXPECT_EQ(e.maximum, 4u);
    EXPECT_GT(e.requested, 4u);
  }
  EXPECT_EQ(l.state_hash(), before);
  EXPECT_EQ(l.stats().cells, 1u);
}

// A world made past its vertex limit (the limit is not checked at construction) refuses every
// edit that leaves it past, even one that adds no vertex.
TEST(LandscapeLimitsHold, AWorldPastItsVertexLimitRefusesEditsThatLeaveItPast) {
  Landscape l({{0, 0}, {1024, 1024}}, 1, {}, {.max_vertices = 3});
  const std::uint64_t before = l.state_hash();
  try {
    l.carve(PolygonSet{square(0, 0, 1024 - 16)});  // leaves an L of 6 vertices
    FAIL();
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit, LimitExceeded::Limit::kVertices);
    EXPECT_EQ(std::string(e.what()).find("landscape vertex limit exceeded: "), 0u);
  }
  try {
    l.carve(PolygonSet{{{0, 512}, {1024, 512}, {1024, 1024}, {0, 1024}}});  // a 4-vertex half
    FAIL();
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit, LimitExceeded::Limit::kVertices);
    EXPECT_EQ(e.requested, 4u);
    EXPECT_EQ(e.maximum, 3u);
  }
  EXPECT_EQ(l.state_hash(), before);
  // Carving everything leaves no vertex: allowed.
  l.carve(PolygonSet{square(0, 0, 1024)});
  EXPECT_EQ(l.stats().vertices, 0u);
}

// A cell at min_cell_size holds any number of edges: it may not split.
TEST(LandscapeLimitsHold, ACellAtTheMinimumSizeKeepsEveryEdge) {
  Landscape l({{0, 0}, {64, 64}}, kEmpty, {.edge_cap = 32, .merge_below = 8, .min_cell_size = 64});
  l.set_checked(true);
  Polygon stairs;
  for (std::int64_t i = 0; i < 30; ++i) {
    stairs.push_back({i, i});
    stairs.push_back({i + 1, i});
  }
  stairs.push_back({30, 60});
  stairs.push_back({0, 60});
  l.fill(PolygonSet{stairs}, 2);
  EXPECT_EQ(l.stats().cells, 1u);
  EXPECT_EQ(l.stats().vertices, 62u);
  EXPECT_TRUE(l.check().ok());
}

// --- materials
// ------------------------------------------------------------------------------------

// A number past the int64 range is reported saturated (errors.hpp: InvalidMaterial::number).
TEST(MaterialNumbers, ANumberPastInt64IsReportedSaturated) {
  try {
    const Material m(std::numeric_limits<std::uint64_t>::max());
    FAIL() << int{m.value()};
  } catch (const InvalidMaterial& e) {
    EXPECT_EQ(e.number, std::numeric_limits<std::int64_t>::max());
    EXPECT_EQ(std::string(e.what()), "material 9223372036854775807 outside 0..255");
  }
  try {
    const Material m(std::uint64_t{256});
    FAIL() << int{m.value()};
  } catch (const InvalidMaterial& e) {
    EXPECT_EQ(e.number, 256);
  }
}

// Starting a recording that is already running changes nothing.
TEST(LandscapeLog, StartingItTwiceKeepsTheRecording) {
  Landscape l({{0, 0}, {1024, 1024}}, 1);
  l.start_log();
  l.carve(PolygonSet{square(10, 10, 20)});
  const std::string recorded = l.log();
  l.start_log();
  EXPECT_EQ(l.log(), recorded);
  EXPECT_EQ(recorded.rfind("world 0 0 1024 1024 1\ncarve MULTIPOLYGON", 0), 0u);
}

}  // namespace
}  // namespace edgeland::test
