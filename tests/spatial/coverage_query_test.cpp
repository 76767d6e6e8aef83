// Queries in the cases the other query tests pass by (spatial/README.md, "Queries"): a second
// polygon of a material already found, a segment of no length, a ray stopping at the first of
// several polygons of one cell, an end point beyond the bound; each answer worked out by hand.
#include <gtest/gtest.h>

#include <vector>

#include "edgeland/spatial/landscape.hpp"
#include "node.hpp"

namespace edgeland::test {
namespace {

Polygon square(std::int64_t x, std::int64_t y, std::int64_t side) {
  return {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
}

// Two squares of material 1 and one of material 2 in one cell.
Landscape three_squares() {
  Landscape l({{0, 0}, {1024, 1024}});
  l.fill(PolygonSet{square(100, 100, 50), square(300, 100, 50)}, 1);
  l.fill(PolygonSet{square(500, 100, 50)}, 2);
  return l;
}

TEST(QueryCases, ASecondPolygonOfAFoundMaterialChangesNothing) {
  const Landscape l = three_squares();
  EXPECT_EQ(l.overlaps(Box64{{120, 120}, {320, 130}}), (std::vector<Material>{1}));
  EXPECT_EQ(l.overlaps(Box64{{120, 120}, {520, 130}}), (std::vector<Material>{1, 2}));
  const ValidSet band(PolygonSet{square(120, 120, 10), square(320, 120, 10)});
  EXPECT_EQ(l.overlaps(band), (std::vector<Material>{1}));
  const ValidSet wide(PolygonSet{{{120, 120}, {520, 120}, {520, 130}, {120, 130}}});
  EXPECT_EQ(l.overlaps(wide), (std::vector<Material>{1, 2}));
  // Touching along a side is not overlapping.
  EXPECT_TRUE(l.overlaps(ValidSet(PolygonSet{square(150, 100, 50)})).empty());
  EXPECT_TRUE(l.overlaps(Box64{{150, 100}, {200, 150}}).empty());
}

TEST(QueryCases, ASegmentOfNoLengthCrossesNothing) {
  const Landscape l = three_squares();
  EXPECT_TRUE(l.crossings({120, 120}, {120, 120}).empty());
  EXPECT_FALSE(l.raycast({10, 10}, {10, 10}).has_value());
}

// A ray through all three squares stops at the first; the crossings of the others, already
// gathered from the same cell, are dropped.
TEST(QueryCases, ARayStopsAtTheFirstOfSeveralPolygonsInACell) {
  const Landscape l = three_squares();
  ASSERT_EQ(l.stats().cells, 1u);
  const auto hit = l.raycast({0, 125}, {1000, 125});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->rounded, (Point64{100, 125}));
  EXPECT_EQ(hit->before, kEmpty);
  EXPECT_EQ(hit->after, Material(1));
  EXPECT_EQ(hit->normal, (Point64{-50, 0}));  // the west side, pointing out
  // From inside the first square the ray leaves it (a back face, passed over) and hits the
  // second.
  const auto next = l.raycast({125, 125}, {1000, 125});
  ASSERT_TRUE(next.has_value());
  EXPECT_EQ(next->rounded, (Point64{300, 125}));
  EXPECT_EQ(l.crossings({0, 125}, {1000, 125}).size(), 6u);
}

TEST(QueryCases, AnEndBeyondTheBoundIsRefused) {
  const Landscape l = three_squares();
  EXPECT_THROW(l.crossings({0, 0}, {kCoordBound + 1, 0}), CoordinateOutOfRange);
  EXPECT_THROW(l.raycast({0, 0}, {0, -kCoordBound - 1}), CoordinateOutOfRange);
  EXPECT_THROW(l.raycast({kCoordBound + 1, 0}, {0, 0}), CoordinateOutOfRange);
}

// A cell's label reads back as a Material only when it is one (labels 1..255 by I1): a broken
// node cannot hand out a wrapped material.
TEST(QueryCases, ANodeLabelOutsideTheMaterialsIsRefused) {
  const detail::NodePtr cell =
      detail::make_cell({{0, 0}, {64, 64}}, 0, {ValidSet(PolygonSet{square(0, 0, 8)}), {300}}, {1});
  EXPECT_THROW(cell->material(0), InvalidMaterial);
  const detail::NodePtr good =
      detail::make_cell({{0, 0}, {64, 64}}, 0, {ValidSet(PolygonSet{square(0, 0, 8)}), {255}}, {1});
  EXPECT_EQ(good->material(0), Material(255));
}

}  // namespace
}  // namespace edgeland::test
