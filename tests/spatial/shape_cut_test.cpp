// Stage test of a big shape cut to the touched cells (spatial/src/shape_cut.hpp, issue 27 point
// 6), and edits with such shapes: every invariant holds (checked mode), seams are exact, the
// materials are the exact history away from the shape's boundary, and a comb set carved back out
// of what its fill made leaves nothing.
#include "shape_cut.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numbers>

#include "cgal_reference.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "state_of.hpp"

namespace edgeland {
namespace {

// A comb on a base [x0, x0 + 2 teeth + 1] x [y0, y0 + 4]: teeth one unit wide and one apart,
// `height` high (axis-parallel: every crossing with a cell line is an integer point).
Polygon comb(std::int64_t x0, std::int64_t y0, std::int64_t teeth, std::int64_t height) {
  const std::int64_t x1 = x0 + 2 * teeth + 1, top = y0 + 4;
  Polygon p{{x0, y0}, {x1, y0}, {x1, top}};
  for (std::int64_t i = teeth; i-- > 0;) {
    const std::int64_t tx = x0 + 1 + 2 * i;
    p.insert(p.end(), {{tx + 1, top}, {tx + 1, top + height}, {tx, top + height}, {tx, top}});
  }
  p.push_back({x0, top});
  return p;
}

// A star of n points between radii r and r_in round c, vertices rounded (the test's own input).
Polygon star(Point64 c, double r, double r_in, int n, double turn) {
  Polygon p;
  for (int i = 0; i < 2 * n; ++i) {
    const double a = std::numbers::pi * i / n + turn, radius = i % 2 == 0 ? r : r_in;
    p.push_back(
        {c.x + std::llround(radius * std::cos(a)), c.y + std::llround(radius * std::sin(a))});
  }
  return p;
}

// A 1024 x 1024 world of rock, split into many cells by a few fills of ore.
Landscape worn_world() {
  LandscapeConfig config;
  config.edge_cap = 32;
  config.merge_below = 10;
  Landscape l({{0, 0}, {1024, 1024}}, 1, config);
  for (int i = 0; i < 6; ++i)
    l.fill(PolygonSet{star({100 + 150 * i, 150 + 120 * i}, 60, 25, 12, 0.1 * i)}, 2);
  return l;
}

Box64 box_of(const detail::Node& n) { return n.box; }

// The exact region of one material's polygons.
test::ExactRegion region_of(const Landscape& l, Material m) {
  PolygonSet members;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    if (v.material == m) members.push_back(*v.polygon);
    return true;
  });
  return test::ExactRegion::of(members);
}

TEST(ShapeCut, SmallShapesAreNotCut) {
  const detail::LandscapeState l = test::state_of(worn_world());
  const ValidSet shape(PolygonSet{star({500, 500}, 400, 380, 16, 0)});  // 32 vertices, many cells
  EXPECT_FALSE(
      detail::cut_shape_to_cells(l.root, shape, *bounding_box(shape.polygons()), {}).has_value());
}

TEST(ShapeCut, ManyMembersReachingFewCellsEachAreNotCut) {
  const detail::LandscapeState l = test::state_of(worn_world());
  PolygonSet squares;  // 400 vertices, each member in one or two cells
  for (std::int64_t i = 0; i < 10; ++i)
    for (std::int64_t j = 0; j < 10; ++j)
      squares.push_back({{10 + 100 * i, 10 + 100 * j},
                         {14 + 100 * i, 10 + 100 * j},
                         {14 + 100 * i, 14 + 100 * j},
                         {10 + 100 * i, 14 + 100 * j}});
  const ValidSet shape(squares);
  EXPECT_FALSE(
      detail::cut_shape_to_cells(l.root, shape, *bounding_box(shape.polygons()), {}).has_value());
}

TEST(ShapeCut, AxisParallelPiecesReuniteIntoTheShape) {
  const detail::LandscapeState l = test::state_of(worn_world());
  const Polygon c = comb(20, 300, 400, 300);  // 1,604 vertices over many cells
  const ValidSet shape(PolygonSet{c});
  const auto cut = detail::cut_shape_to_cells(l.root, shape, *bounding_box(c), {});
  ASSERT_TRUE(cut.has_value());
  EXPECT_GT(cut->pieces.size(), 8u);
  PolygonSet all;
  for (const auto& [cell, pieces] : cut->pieces)
    for (const Polygon& p : pieces.polygons()) {
      const Box64 b = *bounding_box(p);
      EXPECT_TRUE(box_of(*cell).contains(b.min) && box_of(*cell).contains(b.max));
      all.push_back(p);
    }
  // Every crossing of an axis-parallel shape with a cell line is an integer point: nothing is
  // rounded, and the pieces re-unite into the comb itself.
  const std::vector<RegionLabel> ones(all.size(), 1);
  const LabeledClipResult merged =
      relabel(ValidSet(all), ones, ValidSet(), {{0, 0}, {1024, 1024}}, {});
  EXPECT_EQ(merged.stats.vertices_snapped, 0u);
  EXPECT_EQ(merged.regions.set.polygons(), PolygonSet{c});
}

TEST(LandscapeShapeCut, ACombSetCarvedBackLeavesNothing) {
  Landscape l({{0, 0}, {1024, 1024}}, kEmpty);
  l.set_checked(true);
  PolygonSet combs;
  for (std::int64_t k = 0; k < 3; ++k) combs.push_back(comb(8, 40 + 330 * k, 480, 250));
  l.fill(combs, 1);
  ASSERT_GT(l.stats().cells, 100u);  // the fill split the world: the carve back is cut
  EXPECT_EQ(static_cast<long long>(l.twice_area(1)), 3 * 2 * (4 * 961 + 480 * 250));
  l.carve(combs);
  EXPECT_EQ(static_cast<long long>(l.twice_area(1)), 0);
  EXPECT_EQ(l.stats().polygons, 0u);
  EXPECT_TRUE(l.check().ok());
}

// Big stars (the cut path) into a worn world, every invariant checked after the edit; at random
// points two units or more from the star's boundary the material is the exact history's (the
// star's edges are rounded at most twice near cell lines: once by the cut, once by the cell's
// overlay, each within a unit). The world's own boundaries near the star may move by its
// rounding too, so points within two units of them are not compared: found exactly, since the
// ore's star tips are thinner than a unit and pass between any sample points around p (a seed
// found p = (192, 265) half a unit from a tip, rock at p and at all four corners two units away,
// and ore at p once the carve's rounding had moved the tip by less than a unit).
RC_GTEST_PROP(LandscapeShapeCut, BigShapesKeepEveryInvariantAndTheExactMaterials, ()) {
  Landscape l = worn_world();
  l.set_checked(true);
  const Point64 c{*rc::gen::inRange<std::int64_t>(200, 824),
                  *rc::gen::inRange<std::int64_t>(200, 824)};
  const int points = *rc::gen::inRange(150, 300);
  const double r = *rc::gen::inRange(150, 400), r_in = r * *rc::gen::inRange(50, 95) / 100.0;
  const Polygon s = star(c, r, r_in, points, *rc::gen::inRange(0, 1000) / 1000.0);
  const ValidSet shape(PolygonSet{s});
  const bool cut =
      detail::cut_shape_to_cells(test::state_of(l).root, shape, *bounding_box(s), {}).has_value();
  RC_TAG(cut ? "cut to the cells" : "not cut");
  const Landscape before = l;
  const int kind = *rc::gen::inRange(0, 3);
  if (kind == 0) l.carve(PolygonSet{s});
  if (kind == 1) l.fill(PolygonSet{s}, 3);
  if (kind == 2) l.replace(PolygonSet{s}, 1, 4);
  RC_ASSERT(l.check().ok());
  const test::ExactRegion exact = test::ExactRegion::of(PolygonSet{s});
  const test::ExactRegion ore = region_of(before, 2);
  for (int k = 0; k < 200; ++k) {
    const Point64 p{*rc::gen::inRange<std::int64_t>(0, 1024),
                    *rc::gen::inRange<std::int64_t>(0, 1024)};
    const test::QPoint q{test::Rational(p.x), test::Rational(p.y)};
    if (exact.boundary_within(q, test::Rational(4))) continue;
    const bool inside = exact.locate(q) == test::ExactRegion::Location::kInside;
    if (ore.boundary_within(q, test::Rational(4))) continue;
    const Material was = before.material_at(p);
    Material want = was;
    if (inside && kind == 0) want = kEmpty;
    if (inside && kind == 1) want = 3;
    if (inside && kind == 2 && was == Material(1)) want = 4;
    RC_ASSERT(l.material_at(p) == want);
  }
}

}  // namespace
}  // namespace edgeland
