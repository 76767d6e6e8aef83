// The plane graph chains untouched segments into one polyline edge (clip/src/plane_graph.hpp).
// These cases put what the labeling must see through such edges in every place it can be:
// a component whose smallest vertex lies directly above a chain's interior vertex, above the
// interior of a chain piece running east or west, above the top of a vertical chain piece,
// inside a ring that nothing touches, and rings touched in one spot with long chains on either
// side. Every result is checked against the exact CGAL reference (accuracy_contract.hpp).
#include <gtest/gtest.h>

#include "all_ops_check.hpp"
#include "polygon_set_helpers.hpp"

namespace edgeland::test {
namespace {

// A ring with many vertices and no two consecutive edges collinear along its bottom: a valley
// from (0, 100) down to (100, 0) and up to (200, 100), then straight up and back west.
Polygon valley() {
  Polygon p;
  for (std::int64_t i = 0; i <= 20; ++i) p.push_back({10 * i, (i - 10) * (i - 10)});
  p.push_back({200, 500});
  p.push_back({100, 510});
  p.push_back({0, 500});
  return p;
}

// A staircase bottom with vertical and horizontal pieces, and a flat top.
Polygon staircase() {
  Polygon p{{0, 0}};
  for (std::int64_t i = 0; i < 8; ++i) {
    const std::int64_t x = 10 * i, y = (i % 2 == 0) ? 0 : -5;
    p.push_back({x + 10, y});
    p.push_back({x + 10, (i % 2 == 0) ? -5 : 0});
  }
  p.push_back({80, 50});
  p.push_back({40, 55});
  p.push_back({0, 50});
  return p;
}

Polygon square(std::int64_t x, std::int64_t y, std::int64_t side) {
  return {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
}

TEST(ChainedEdges, ComponentDirectlyAboveAChainVertex) {
  // (50, 25) is an interior vertex of the valley's untouched chain; the square starts at
  // (50, 40), inside the valley.
  expect_all_ops_exact({valley()}, {square(50, 40, 10)});
}

TEST(ChainedEdges, ComponentAboveTheInteriorOfAnEastwardChainPiece) {
  // Below (55, 40) is the piece (50, 25)-(60, 16), which runs east: its left side is above.
  expect_all_ops_exact({valley()}, {square(55, 40, 10)});
}

// (Operands whose boxes do not overlap skip the pipeline altogether, clip.cpp: the clip
// operands below reach into the valley's box.)
TEST(ChainedEdges, ComponentAboveAWestwardChainPieceOutsideTheRing) {
  // Below (30, 506) is the valley's top piece (100, 510)-(0, 500), running west: outside above.
  expect_all_ops_exact({valley()}, {square(30, 506, 10)});
  // Directly above the top chain's vertex (100, 510).
  expect_all_ops_exact({valley()}, {{{100, 512}, {150, 507}, {160, 530}, {100, 530}}});
}

TEST(ChainedEdges, ComponentAboveTheTopOfAVerticalChainPiece) {
  // (10, 0)-(10, -5) and (30, 0)-(30, -5) are vertical pieces of the staircase's chain.
  expect_all_ops_exact({staircase()}, {square(10, 20, 5)});
  expect_all_ops_exact({staircase()}, {square(30, 20, 5)});
  // Above a horizontal piece's interior at the bottom of a step.
  expect_all_ops_exact({staircase()}, {square(15, 20, 5)});
}

TEST(ChainedEdges, ComponentBelowARingIsOutsideIt) {
  // Inside the valley's box, under its left slope: nothing below, outside everything.
  expect_all_ops_exact({valley()}, {square(5, 10, 10)});
  expect_all_ops_exact({valley()}, {square(45, 10, 4)});
}

TEST(ChainedEdges, UntouchedRingInsideAnotherOperandsUntouchedRing) {
  // Subject: the staircase and a small square far right; clip: a ring around the small
  // square only. Nothing touches anything: every ring is chains only.
  const PolygonSet a{staircase(), square(300, 10, 20)};
  Polygon around;
  for (std::int64_t i = 0; i < 12; ++i) around.push_back({280 + 5 * i, 0 - i});
  around.push_back({350, -20});
  around.push_back({350, 50});
  around.push_back({280, 50});
  expect_all_ops_exact(a, {around});
}

// Labeling scans every piece for the first four components it must locate and builds a
// segment tree from the fifth on: twelve untouched squares, some inside the valley, some
// outside it, some above its top vertex, take both paths.
TEST(ChainedEdges, ManyUntouchedComponentsAreLocatedBothWays) {
  PolygonSet squares;
  for (std::int64_t k = 0; k < 12; ++k) squares.push_back(square(10 + 16 * k, 120 + 37 * k, 6));
  expect_all_ops_exact({valley()}, squares);
}

TEST(ChainedEdges, RingsTouchedInOneSpotKeepLongChainsOnEitherSide) {
  // A triangle crossing one bottom edge of the valley; a square touching the valley's top at a
  // single vertex; a square sharing part of the valley's right side.
  expect_all_ops_exact({valley()}, {{{52, 0}, {68, 0}, {60, 40}}});
  expect_all_ops_exact({valley()}, {{{90, 510}, {110, 510}, {100, 520}}});
  expect_all_ops_exact({valley()}, {square(200, 200, 50)});
}

TEST(ChainedEdges, NestedRingsUnderEveryFillRule) {
  // Squares with extra points on their sides (chains of collinear segments): outer CCW,
  // middle CW, inner CCW. Winding numbers: band 1, middle band 0, core 1.
  auto dotted = [](std::int64_t lo, std::int64_t hi, bool ccw) {
    Ring r;
    for (std::int64_t x = lo; x < hi; x += 5) r.push_back({x, lo});
    for (std::int64_t y = lo; y < hi; y += 5) r.push_back({hi, y});
    for (std::int64_t x = hi; x > lo; x -= 5) r.push_back({x, hi});
    for (std::int64_t y = hi; y > lo; y -= 5) r.push_back({lo, y});
    if (!ccw) std::reverse(r.begin(), r.end());
    return r;
  };
  const std::vector<Ring> rings{dotted(0, 100, true), dotted(20, 80, false), dotted(40, 60, true)};
  const Int128 filled = 2 * (100 * 100 - 60 * 60 + 20 * 20);  // twice the area
  for (FillRule rule :
       {FillRule::kEvenOdd, FillRule::kNonZero, FillRule::kPositive, FillRule::kNegative}) {
    const Outcome o = run_normalize(rings, rule);
    ASSERT_TRUE(o.ok()) << o.error;
    EXPECT_EQ(twice_area(o.result->polygons), rule == FillRule::kNegative ? Int128(0) : filled)
        << fill_rule_name(rule);
  }
}

}  // namespace
}  // namespace edgeland::test
