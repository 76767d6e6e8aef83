// triangulate.hpp: exact triangulation. Every result is checked by tests/support/piece_checks
// (written apart from the kernel's triangulation): n - 2 counter-clockwise triangles of
// positive area, exact area sum, disjoint interiors, and each side a polygon edge or a diagonal
// inside the polygon (brute force) or the union equal to the polygon (the clipper's xor).
#include "edgeland/kernel/triangulate.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdio>
#include <set>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/validate.hpp"
#include "support/generators.hpp"
#include "support/grid_polygons.hpp"
#include "support/piece_checks.hpp"
#include "support/piece_shapes.hpp"
#include "support/rc_grid_draws.hpp"
#include "support/validate_generators.hpp"

namespace edgeland::testing {
namespace {

// Every property, with the O(n^2) diagonal check for small polygons, else the clipper's xor.
std::string defect(const Polygon& polygon) {
  const std::vector<Triangle> triangles = triangulate(polygon);
  if (std::string d = triangulation_defect(polygon, triangles); !d.empty()) return d;
  if (polygon.size() <= 400) return diagonal_defect(polygon, triangles);
  return union_defect(polygon, triangle_polygons(polygon, triangles));
}

#define EXPECT_TRIANGULATED(polygon)           \
  do {                                         \
    const Polygon p_ = (polygon);              \
    ASSERT_TRUE(validate(p_).ok());            \
    EXPECT_EQ(defect(p_), "") << to_wkt({p_}); \
  } while (false)

TEST(Triangulate, TriangleIsItself) {
  const std::vector<Triangle> t = triangulate({{0, 0}, {1, 0}, {0, 1}});
  ASSERT_EQ(t.size(), 1u);
  const std::set<std::uint32_t> corners{t[0].a, t[0].b, t[0].c};
  EXPECT_EQ(corners, (std::set<std::uint32_t>{0, 1, 2}));
}

TEST(Triangulate, SquareWithStraightVerticesOnEverySide) {
  EXPECT_TRIANGULATED((Polygon{{0, 0},
                               {1, 0},
                               {2, 0},
                               {3, 0},
                               {3, 1},
                               {3, 2},
                               {3, 3},
                               {2, 3},
                               {1, 3},
                               {0, 3},
                               {0, 2},
                               {0, 1}}));
}

TEST(Triangulate, TriangleWithOneMidpointPerSide) {
  // Each midpoint is straight: it must be a corner of a triangle reaching across.
  EXPECT_TRIANGULATED((Polygon{{0, 0}, {2, 0}, {4, 0}, {3, 2}, {2, 4}, {1, 2}}));
}

TEST(Triangulate, TriangleWithManyPointsOnOneSide) {
  Polygon p;
  for (std::int64_t x = 0; x <= 50; ++x) p.push_back({x, 0});
  p.push_back({25, 7});
  EXPECT_TRIANGULATED(p);  // a fan from the apex: the only one
}

TEST(Triangulate, StraightChainPointingAtTheOtherChain) {
  // The left chain runs straight through (0,10), (-2,9), (-4,8) toward (-8,6) on the right
  // chain: a fan from (-8,6) over that run would hold a flat triangle (kernel/README.md).
  EXPECT_TRIANGULATED(
      (Polygon{{1, 12}, {0, 10}, {-2, 9}, {-4, 8}, {-20, 4}, {-10, 0}, {-8, 6}, {5, 11}}));
  // Mirrored: the same on the right chain.
  EXPECT_TRIANGULATED(
      (Polygon{{-1, 12}, {-5, 11}, {8, 6}, {10, 0}, {20, 4}, {4, 8}, {2, 9}, {0, 10}}));
}

TEST(Triangulate, HorizontalEdgesAndLevelVertices) {
  // A staircase: every vertex level with a neighbour, split and merge vertices on one height.
  EXPECT_TRIANGULATED((Polygon{{0, 0},
                               {6, 0},
                               {6, 2},
                               {5, 2},
                               {5, 1},
                               {4, 1},
                               {4, 2},
                               {2, 2},
                               {2, 1},
                               {1, 1},
                               {1, 2},
                               {0, 2}}));
  EXPECT_TRIANGULATED((Polygon{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {3, 2}, {3, 3}, {0, 3}}));
}

TEST(Triangulate, ZigzagBandOfSplitAndMergeVertices) { EXPECT_TRIANGULATED(zigzag_band(40)); }

TEST(Triangulate, CombWithOneUnitTeeth) {
  EXPECT_TRIANGULATED(unit_comb(60, 1));
  EXPECT_TRIANGULATED(unit_comb(60, 9));
  // Sideways and upside down: the teeth now meet the sweep as split or merge vertices.
  for (const test::Affine& turn :
       {test::Affine{0, -1, 1, 0, 0, 0}, test::Affine{-1, 0, 0, -1, 0, 0},
        test::Affine{0, 1, -1, 0, 0, 0}, test::Affine{1, 3, 0, 1, 0, 0}}) {
    EXPECT_TRIANGULATED(turn.apply({unit_comb(30, 4)})->front());
  }
}

TEST(Triangulate, SpiralWithEveryLatticePointAVertex) {
  const Polygon spiral = *polyomino_boundary(spiral_cells(17));
  EXPECT_TRIANGULATED(spiral);
  EXPECT_TRIANGULATED(without_straight_vertices(spiral));
  EXPECT_TRIANGULATED(test::Affine({2, 1, 1, 1, 0, 0}).apply({spiral})->front());
}

TEST(Triangulate, SliverOneUnitWide) {
  EXPECT_TRIANGULATED((Polygon{{0, 0}, {1000, 999}, {1000, 1000}}));  // area 1/2
  EXPECT_TRIANGULATED((Polygon{{0, 0}, {500, 1}, {1000, 2}, {1000, 3}, {500, 2}, {0, 1}}));
}

TEST(Triangulate, FullCoordinateRange) {
  constexpr std::int64_t B = kCoordBound;
  EXPECT_TRIANGULATED((Polygon{{-B, -B}, {0, -B}, {B, -B}, {B, B}, {0, 0}, {-B, B}}));
  EXPECT_TRIANGULATED((Polygon{{-B, -B}, {B, -B + 1}, {B, -B + 2}, {-B, -B + 1}}));
}

TEST(Triangulate, RejectsInvalidPolygonsWithTheirViolation) {
  try {
    triangulate({{0, 0}, {2, 2}, {2, 0}, {0, 2}});  // a bow tie
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.operand, Operand::kPolygon);
    EXPECT_EQ(e.violation.rule, Rule::kSelfIntersection);
  }
  try {
    triangulate({{0, 0}, {0, 1}, {1, 0}});  // clockwise
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.violation.rule, Rule::kNotCounterClockwise);
  }
  EXPECT_THROW(triangulate({{0, 0}, {kCoordBound + 1, 0}, {0, 1}}), CoordinateOutOfRange);
  EXPECT_THROW(triangulate({{0, 0}, {1, 0}}), InvalidInput);
}

TEST(TriangulateExhaustive, EveryPolygonOnSmallGrids) {
  struct Case {
    std::int64_t w, h;
    std::size_t max_vertices;
  };
  for (const Case c : {Case{3, 3, 9}, Case{4, 3, 7}, Case{5, 2, 10}, Case{4, 4, 6}}) {
    std::size_t polygons = 0, straight = 0;
    GridPolygons(c.w, c.h, c.max_vertices).for_each([&](const Polygon& p) {
      ++polygons;
      if (without_straight_vertices(p).size() != p.size()) ++straight;
      const std::string d = defect(p);
      ASSERT_EQ(d, "") << to_wkt({p});
    });
    std::printf("%lldx%lld grid, up to %zu vertices: %zu polygons (%zu with straight vertices)\n",
                static_cast<long long>(c.w), static_cast<long long>(c.h), c.max_vertices, polygons,
                straight);
    EXPECT_GT(straight, 0u);
  }
}

// A random valid polygon: generators.hpp's shapes, polyominoes (all lattice points kept, some
// sheared), boxes with vertices on their sides, and members of normalized random rings.
Polygon random_polygon() {
  RcDraw draw;
  switch (draw(0, 5)) {
    case 0:
      return *test::gen::shape({draw(-50, 50), draw(-50, 50)}, draw(2, 60));
    case 1: {
      const auto p = random_polyomino(draw, static_cast<std::size_t>(draw(1, 60)), draw(1, 4));
      if (!p) return {{0, 0}, {1, 0}, {0, 1}};
      const test::Affine shear{1, draw(-2, 3), 0, 1, 0, 0};
      return draw(0, 2) == 0 ? *p : shear.apply({*p})->front();
    }
    case 2:
      return box_with_side_vertices(draw, draw(2, 30), draw(2, 30),
                                    static_cast<std::size_t>(draw(0, 12)));
    default: {
      std::vector<Ring> rings(static_cast<std::size_t>(draw(1, 4)));
      for (Ring& r : rings)
        for (std::int64_t k = draw(3, 12); k > 0; --k) r.push_back({draw(0, 12), draw(0, 12)});
      const PolygonSet set = normalize(rings, FillRule::kNonZero).polygons;
      if (set.empty()) return {{0, 0}, {1, 0}, {0, 1}};
      return set[static_cast<std::size_t>(draw(0, static_cast<std::int64_t>(set.size())))];
    }
  }
}

RC_GTEST_PROP(TriangulateProperty, RandomValidPolygons, ()) {
  const Polygon p = random_polygon();
  RC_PRE(validate(p, 1).ok());
  RC_ASSERT(defect(p) == "");
}

RC_GTEST_PROP(TriangulateProperty, AnyStartingVertex, ()) {
  Polygon p = random_polygon();
  RC_PRE(validate(p, 1).ok());
  std::rotate(p.begin(), p.begin() + *rc::gen::inRange<std::size_t>(0, p.size()), p.end());
  RC_ASSERT(defect(p) == "");
}

// 10^5 vertices: the sweep stays O(n log n) (a quadratic step would not finish in the test's
// time), and every property holds.
TEST(TriangulateLarge, HundredThousandVertices) {
  SplitMixDraw draw(26);
  const std::vector<Polygon> polygons{
      random_star(draw, {0, 0}, 1'000'000, 100'000),
      unit_comb(25'000, 3),
      *polyomino_boundary(spiral_cells(300)),
      box_with_side_vertices(draw, 1'000'000, 1'000'000, 25'000),
  };
  for (const Polygon& p : polygons) {
    ASSERT_TRUE(validate(p).ok());
    ASSERT_GE(p.size(), 90'000u);
    const std::vector<Triangle> t = triangulate(p);
    EXPECT_EQ(triangulation_defect(p, t), "");
  }
}

}  // namespace
}  // namespace edgeland::testing
