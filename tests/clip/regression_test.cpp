// Minimized failures found by the property tests of this directory, kept as permanent cases.
// Each names the property that found it; the inputs were shrunk by hand / greedy deletion
// while the failure persisted. See the report of issue 4's verification for the analysis.
#include <gtest/gtest.h>

#include "accuracy_contract.hpp"
#include "all_ops_check.hpp"
#include "checked_clip.hpp"
#include "locality_check.hpp"
#include "polygon_set_helpers.hpp"

namespace edgeland::test {
namespace {

// Both sides of the locality oracle (tests/support/locality_check.hpp).
std::string locality_failure(ClipOp op, const char* a_wkt, const char* b_wkt) {
  const PolygonSet a = parse_wkt(a_wkt), b = parse_wkt(b_wkt);
  const Outcome o = run_clip(op, a, b);
  if (!o.ok()) return o.error;
  std::string f = check_locality(op, a, b, true, o.result->polygons);
  if (f.empty()) f = check_locality(op, b, a, false, o.result->polygons);
  return f.empty() ? f : f + "\n  output = " + to_wkt(o.result->polygons);
}

// ClipLocality: A is a needle of area 1/2 (thinner than a pixel all along). B crosses it near
// (7 0), and snap rounding reroutes A's long edge (0 1)-(8 0) through the vertex pixel (1 1),
// 3.9 units from B: the long edges then cancel along (0 1)-(1 1), and the edge (1 1)-(0 1),
// farther than 2 from B's boundary, is missing from A + B although union keeps A whole.
TEST(ClipLocalityRegression, NeedleTipFarFromTheCutSurvivesUnion) {
  EXPECT_EQ(locality_failure(ClipOp::kUnion, "POLYGON ((8 0, 1 1, 0 1, 8 0))",
                             "POLYGON ((7 0, 2 6, 1 7, 7 0))"),
            "");
}

// ClipLocality: the same collapse in a difference; A's edge (22 9)-(22 10) is 3.1 units from
// B's boundary and outside B, so A - B must keep it.
TEST(ClipLocalityRegression, NeedleTipFarFromTheCutSurvivesDifference) {
  EXPECT_EQ(locality_failure(ClipOp::kDifference, "POLYGON ((21 14, 22 9, 22 10, 21 14))",
                             "POLYGON ((53 33, 0 0, 37 23, 53 33))"),
            "");
}

// ClipLocality (unminimized, a realistic shape): a sheared comb with one-unit teeth, unioned
// with a square whose edge x = -30 crosses the last teeth. The hot-pixel closure walks from
// tooth to tooth: the tooth edge (-33 -36)-(-35 -37), 3 units from the square's boundary, is
// rerouted through (-34 -37).
TEST(ClipLocalityRegression, HotPixelCascadeAlongAOneUnitComb) {
  EXPECT_EQ(locality_failure(ClipOp::kUnion,
                             "POLYGON ((-39 -38, -29 -38, -27 -37, -32 -37, -28 -35, -29 -35, "
                             "-33 -37, -34 -37, -32 -36, -33 -36, -35 -37, -37 -37, -39 -38))",
                             "POLYGON ((-40 -40, -30 -40, -30 -30, -40 -30, -40 -40))"),
            "");
}

// ClipLocality (an oracle case, kept so that it stays right): B's far edge x = -811271609 is
// shared, over part of its length, in reverse by B's other member. There both sides are in B,
// so A - B has an edge only along the rest: the edge is "kept" piece by piece, cut at the
// vertex (-811271609 -1574821345) of the other member.
TEST(ClipLocalityRegression, EdgePartlySharedWithAnotherMemberIsKeptPieceByPiece) {
  EXPECT_EQ(locality_failure(
                ClipOp::kDifference,
                "MULTIPOLYGON (((-1383933911 -1383933911, -2147483647 -2147483647, -811271609 "
                "-2147483647, -1383933911 -1383933911)), ((-1383933911 -1383933911, -811271609 "
                "-2147483647, -715827892 -1479377628, -1383933911 -1383933911)))",
                "MULTIPOLYGON (((-811271609 -1383933911, -1193046477 -1670265062, -811271609 "
                "-1574821345, -811271609 -1383933911)), ((-811271609 -1670265062, -715827892 "
                "-1670265062, -811271609 -1479377628, -811271609 -1670265062)))"),
            "");
}

// ClipLocality (an oracle case): another member of A touches A's far edge x = -1654618561 at
// its vertex (-1654618561 -1725027859); in A xor B the two halves bound different output
// polygons and meet there.
TEST(ClipLocalityRegression, EdgeTouchedByAnotherMembersVertexMaySplitThere) {
  EXPECT_EQ(locality_failure(
                ClipOp::kXor,
                "MULTIPOLYGON (((-1830641806 -1584209263, -1619413912 -1584209263, -1619413912 "
                "-1372981369, -1830641806 -1584209263)), ((-1725027859 -1689823210, -1689823210 "
                "-1760232508, -1654618561 -1725027859, -1689823210 -1654618561, -1725027859 "
                "-1689823210)), ((-1654618561 -1760232508, -1619413912 -1830641806, -1654618561 "
                "-1689823210, -1654618561 -1760232508)))",
                "MULTIPOLYGON (((-2147483647 -2147483647, -2006665051 -2147483647, -35204707 -58, "
                "-2147483647 -2077074349, -2147483647 -2147483647)))"),
            "");
}

// fuzz/campaign clip_sequence (tests/regress/clip_sequence/849b25e4...): a ring whose smallest
// vertex (-64 -64) is the tip of a spike folded back onto itself. The spike's two edges cancel,
// so the smallest point left is an interior point of a chain of untouched edges; the labeling
// started west of a vertex that was not the component's smallest and threw (or, for
// kPositive, returned nothing). What remains is the quadrilateral (63 19) (64 21) (63 20)
// (62 19), counter-clockwise, winding +1, twice-area 2; the spike adds no area.
TEST(NormalizeRegression, RingWhoseSmallestVertexIsOnACancelledSpike) {
  const std::vector<Ring> rings{
      {{63, 19}, {64, 21}, {-64, -64}, {64, 21}, {63, 20}, {62, 19}, {62, 19}},
      {{62, 19}, {62, 19}, {62, 19}}};
  for (FillRule rule :
       {FillRule::kEvenOdd, FillRule::kNonZero, FillRule::kPositive, FillRule::kNegative}) {
    const Outcome o = run_normalize(rings, rule);
    ASSERT_TRUE(o.ok()) << o.error;
    EXPECT_EQ(twice_area(o.result->polygons), rule == FillRule::kNegative ? Int128(0) : Int128(2))
        << fill_rule_name(rule);
  }
}

// The clip-operand counterpart: a needle whose smallest vertex is its far tip (its long edges
// stay untouched chains from there) cut across its wide end, against the exact reference.
TEST(ClipRegression, NeedleWhoseTipIsItsSmallestVertex) {
  expect_all_ops_exact(parse_wkt("POLYGON ((-64 -64, 63 20, 64 21, -64 -64))"),
                       parse_wkt("POLYGON ((60 15, 70 15, 70 25, 60 25, 60 15))"));
}

}  // namespace
}  // namespace edgeland::test
