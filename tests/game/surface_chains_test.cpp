// The collision surface (surface_chains.hpp): named worlds whose surface is known, and random
// landscapes against the brute-force reference (surface_oracle.hpp).
#include "edgeland/game/surface_chains.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "chain_rules.hpp"
#include "game_worlds.hpp"
#include "landscape_cases.hpp"
#include "surface_oracle.hpp"

namespace edgeland::test {
namespace {

Polygon rect(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

LandscapeConfig grid(int depth) {
  LandscapeConfig c;
  c.grid_depth = depth;
  return c;
}

// Rock below y = 300 in a 16 x 16 grid of 64-unit cells: the floor is one straight surface
// running west (rock on its left), cut at every cell line.
TEST(SurfaceChains, FlatFloorIsOneRunCutAtCellLinesWithStraightGhosts) {
  Landscape world({{0, 0}, {1024, 1024}}, kEmpty, grid(4));
  world.fill(PolygonSet{rect(0, 0, 1024, 300)}, 1);
  const std::vector<SurfaceChain> chains = surface_chains(world);
  ASSERT_EQ(chains.size(), 16u);
  for (const SurfaceChain& c : chains) {
    EXPECT_EQ(chain_rule_violation(c), "");
    ASSERT_EQ(c.points.size(), 2u);
    const std::int64_t x = c.cell.max.x;
    EXPECT_EQ(c.points[0], (Point64{x, 300}));
    EXPECT_EQ(c.points[1], (Point64{x - 64, 300}));
    EXPECT_EQ(c.ghost_prev, (Point64{x + 64, 300}));  // also beyond the east border: straight on
    EXPECT_EQ(c.ghost_next, (Point64{x - 128, 300}));
    EXPECT_FALSE(c.closed);
    EXPECT_EQ(c.materials, std::vector<Material>{1});
  }
  const std::vector<SurfaceChain> loops = surface_loops(world);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].points, (std::vector<Point64>{{1024, 300}, {0, 300}}));
}

// Two solid materials side by side: the border between them is no surface, the material changes
// where the surface crosses it, and that point is kept although the surface goes straight on.
TEST(SurfaceChains, BorderBetweenTwoSolidsIsNoSurfaceButItsPointIsKept) {
  Landscape world({{0, 0}, {100, 100}});
  world.fill(PolygonSet{rect(10, 10, 50, 50)}, 1);
  world.fill(PolygonSet{rect(50, 10, 90, 50)}, 2);
  const std::vector<SurfaceChain> loops = surface_loops(world);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_TRUE(loops[0].closed);
  EXPECT_EQ(loops[0].points,
            (std::vector<Point64>{{10, 10}, {50, 10}, {90, 10}, {90, 50}, {50, 50}, {10, 50}}));
  EXPECT_EQ(loops[0].materials, (std::vector<Material>{1, 2, 2, 2, 1, 1}));
}

// Water is not solid: rock under water has a surface, water none.
TEST(SurfaceChains, NonSolidMaterialsHaveNoSurface) {
  Landscape world({{0, 0}, {100, 100}});
  world.fill(PolygonSet{rect(0, 0, 100, 40)}, 1);
  world.fill(PolygonSet{rect(0, 40, 100, 60)}, 7);
  SurfaceOptions options;
  options.materials.solid[7] = false;
  EXPECT_EQ(
      surface_difference(surface_brute(world, options), surface_of(surface_chains(world, options))),
      "");
  const std::vector<SurfaceChain> loops = surface_loops(world, options);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].points, (std::vector<Point64>{{100, 40}, {0, 40}}));
}

// With a wall the border closes the empty part of the world: one loop, clockwise around the air
// (the outside, which is solid now, on its left).
TEST(SurfaceChains, BorderWallClosesTheEmptyPart) {
  Landscape world({{0, 0}, {100, 100}}, kEmpty, grid(2));
  world.fill(PolygonSet{rect(0, 0, 100, 40)}, 1);
  SurfaceOptions options;
  options.border_wall = true;
  const std::vector<SurfaceChain> loops = surface_loops(world, options);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_TRUE(loops[0].closed);
  EXPECT_EQ(loops[0].points, (std::vector<Point64>{{0, 40}, {0, 100}, {100, 100}, {100, 40}}));
  EXPECT_EQ(loops[0].materials, (std::vector<Material>{0, 0, 0, 1}));
}

// Two squares of rock touching at one corner stay two loops (the face-tracing rule keeps each
// piece of solid on the left), also when the corner is on a cell line.
TEST(SurfaceChains, SolidsTouchingAtAPointStayApart) {
  Landscape world({{0, 0}, {128, 128}}, kEmpty, grid(1));
  world.fill(PolygonSet{rect(20, 20, 64, 64), rect(64, 64, 100, 100)}, 1);
  const std::vector<SurfaceChain> loops = surface_loops(world);
  ASSERT_EQ(loops.size(), 2u);
  for (const SurfaceChain& loop : loops) {
    EXPECT_TRUE(loop.closed);
    EXPECT_EQ(loop.points.size(), 4u);
  }
}

void expect_matches_reference(const Landscape& world, const SurfaceOptions& options) {
  const SurfaceMap expected = surface_brute(world, options);
  const std::vector<SurfaceChain> chains = surface_chains(world, options);
  for (const SurfaceChain& c : chains) {
    const std::string problem = chain_rule_violation(c);
    if (!problem.empty()) RC_FAIL("chain rule: " + problem);
    for (const Point64& p : c.points) RC_ASSERT(c.cell.contains(p));
  }
  const std::string cells = surface_difference(expected, surface_of(chains));
  if (!cells.empty()) RC_FAIL("per-cell chains: " + cells);
  const std::vector<SurfaceChain> loops = surface_loops(world, options);
  for (const SurfaceChain& c : loops) {
    const std::string problem = chain_rule_violation(c);
    if (!problem.empty()) RC_FAIL("loop rule: " + problem);
  }
  const std::string joined = surface_difference(expected, surface_of(loops));
  if (!joined.empty()) RC_FAIL("loops: " + joined);
}

SurfaceOptions random_options() {
  SurfaceOptions options;
  options.border_wall = *rc::gen::arbitrary<bool>();
  for (int m = 1; m < 6; ++m) options.materials.solid[m] = *rc::gen::inRange(0, 4) != 0;
  return options;
}

RC_GTEST_PROP(SurfaceChainsProperty, ChainsAndLoopsAreExactlyTheSurface, ()) {
  const LandscapeCase c = *landscape_case();
  const Landscape world = run_case(c, c.config);
  expect_matches_reference(world, random_options());
  RC_CLASSIFY(world.stats().cells > 1, "several cells");
}

// A layered world after hundreds of blasts: many cells, bridges, pinches, materials.
TEST(SurfaceChains, LongGameMatchesTheReference) {
  LandscapeConfig config;
  config.edge_cap = 32;
  config.merge_below = 12;
  Landscape world = layered_world(2048, config);
  random_edits(world, 3, 300, [](const ChangeSet&) {});
  ASSERT_GT(world.stats().cells, 100u);
  for (const bool wall : {false, true}) {
    SurfaceOptions options;
    options.border_wall = wall;
    options.materials.solid[2] = false;  // dirt, say, is sand that does not hold a body
    const SurfaceMap expected = surface_brute(world, options);
    const std::vector<SurfaceChain> chains = surface_chains(world, options);
    for (const SurfaceChain& c : chains) ASSERT_EQ(chain_rule_violation(c), "");
    EXPECT_EQ(surface_difference(expected, surface_of(chains)), "");
    EXPECT_EQ(surface_difference(expected, surface_of(surface_loops(world, options))), "");
  }
}

}  // namespace
}  // namespace edgeland::test
