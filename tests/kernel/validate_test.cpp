// validate(): named cases for every rule and for the coordinate bound (thesis chapter 2: the
// polygon model is strictly simple, counter-clockwise rings with disjoint interiors).
// The sweep is checked against the O(n^2) brute force in validate_property_test.cpp.
#include "edgeland/kernel/validate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace edgeland {
namespace {

constexpr std::int64_t B = kCoordBound;

Polygon square(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Polygon reversed(Polygon p) {
  std::reverse(p.begin(), p.end());
  return p;
}

std::set<Rule> rules_of(const ValidationReport& r) {
  std::set<Rule> out;
  for (const Violation& v : r.violations) out.insert(v.rule);
  return out;
}

// The one violation of a report that must have exactly one.
Violation single(const ValidationReport& r) {
  EXPECT_EQ(r.violations.size(), 1u);
  return r.violations.empty() ? Violation{} : r.violations.front();
}

// --- single polygons ---------------------------------------------------------------------

TEST(ValidatePolygon, CounterClockwiseSquareIsValid) {
  EXPECT_TRUE(validate(square(0, 0, 10, 10)).ok());
}

TEST(ValidatePolygon, CollinearVertexOnAStraightSideIsAllowed) {
  EXPECT_TRUE(validate(Polygon{{0, 0}, {5, 0}, {10, 0}, {10, 10}, {0, 10}}).ok());
}

TEST(ValidatePolygon, NonConvexRingWithVerticalEdgesIsValid) {
  // A U shape: vertical edges at one x on both sides of the notch.
  EXPECT_TRUE(
      validate(Polygon{{0, 0}, {9, 0}, {9, 9}, {6, 9}, {6, 3}, {3, 3}, {3, 9}, {0, 9}}).ok());
}

TEST(ValidatePolygon, BowTieCrossesAtItsCentre) {
  // Thesis 2.1, fig. 6 (left): edges that cross make a polygon non-simple.
  const Violation v = single(validate(Polygon{{0, 0}, {10, 10}, {10, 0}, {0, 10}}));
  EXPECT_EQ(v.rule, Rule::kSelfIntersection);
  EXPECT_EQ(v.polygon, 0u);
  EXPECT_EQ(v.edge, 0u);
  EXPECT_EQ(v.other_edge, 2u);
  EXPECT_EQ(v.where, (Point64{5, 5}));
  EXPECT_EQ(v.describe(), "self-intersection: polygon 0 edges 0 and 2 at (5 5)");
}

TEST(ValidatePolygon, RingTouchingItselfAtAVertex) {
  // Thesis 2.1, fig. 6 (right): a self-touching ("weakly simple") polygon, which the thesis
  // excludes. Two triangles joined at (5, 5): the vertex appears twice, 4 edges meet there.
  const Violation v = single(validate(Polygon{{0, 0}, {10, 0}, {5, 5}, {10, 10}, {0, 10}, {5, 5}}));
  EXPECT_EQ(v.rule, Rule::kSelfIntersection);
  EXPECT_EQ(v.where, (Point64{5, 5}));
}

TEST(ValidatePolygon, VertexOnTheInteriorOfANonAdjacentEdge) {
  // Vertex 3 at (5, 0) lies on edge 0.
  const Violation v = single(validate(Polygon{{0, 0}, {10, 0}, {10, 10}, {5, 0}, {0, 10}}));
  EXPECT_EQ(v.rule, Rule::kSelfIntersection);
  EXPECT_EQ(v.where, (Point64{5, 0}));
}

TEST(ValidatePolygon, CrossingAtANonIntegerPointIsReportedRounded) {
  // Edges 0 and 2 cross at (1.5, 0.5), rounded half up to (2, 1).
  const Violation v = single(validate(Polygon{{0, 0}, {3, 1}, {3, 0}, {0, 1}}));
  EXPECT_EQ(v.rule, Rule::kSelfIntersection);
  EXPECT_EQ(v.where, (Point64{2, 1}));
}

TEST(ValidatePolygon, ClockwiseSquareIsNotCounterClockwise) {
  // Thesis 2.2: the signed trapezoid sum is negative for a clockwise ring.
  const Violation v = single(validate(reversed(square(0, 0, 10, 10))));
  EXPECT_EQ(v.rule, Rule::kNotCounterClockwise);
  EXPECT_EQ(v.describe(), "not-counter-clockwise: polygon 0 at (0 0)");
}

TEST(ValidatePolygon, SpikeFoldingBackAlongAnEdge) {
  // Edge 2 runs back down edge 1; its end (10, 5) then lies on edge 1, which edge 3 touches.
  const ValidationReport r = validate(Polygon{{0, 0}, {10, 0}, {10, 10}, {10, 5}, {0, 8}});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.violations.front().rule, Rule::kSpike);
  EXPECT_EQ(r.violations.front().edge, 1u);
  EXPECT_EQ(r.violations.front().other_edge, 2u);
  EXPECT_EQ(r.violations.front().where, (Point64{10, 10}));
  EXPECT_EQ(r.violations.front().describe(), "spike: polygon 0 edges 1 and 2 at (10 10)");
  EXPECT_EQ(rules_of(r), (std::set<Rule>{Rule::kSpike, Rule::kSelfIntersection}));
}

TEST(ValidatePolygon, FlatTriangleIsTwoSpikesAndNoOrientation) {
  // All three vertices on a line: both ends fold back; a ring that is not simple has no
  // meaningful orientation, so none is reported.
  const ValidationReport r = validate(Polygon{{0, 0}, {10, 0}, {5, 0}});
  ASSERT_EQ(r.violations.size(), 2u);
  EXPECT_EQ(rules_of(r), std::set<Rule>{Rule::kSpike});
  EXPECT_EQ(r.violations[0].where, (Point64{0, 0}));
  EXPECT_EQ(r.violations[1].where, (Point64{10, 0}));
}

TEST(ValidatePolygon, PipeToAHoleIsNotSimple) {
  // Thesis 3.6.2, fig. 36: a hole joined to the border by a "pipe", two edges on one line in
  // opposite directions. The thesis drops this representation; such a ring self-touches.
  const Violation v = single(validate(Polygon{{0, 0},
                                              {10, 0},
                                              {10, 10},
                                              {0, 10},
                                              {0, 5},
                                              {3, 5},
                                              {3, 7},
                                              {7, 7},
                                              {7, 3},
                                              {3, 3},
                                              {3, 5},
                                              {0, 5}}));
  EXPECT_EQ(v.rule, Rule::kSelfIntersection);
}

TEST(ValidatePolygon, RepeatedVertex) {
  const Violation v = single(validate(Polygon{{0, 0}, {10, 0}, {10, 0}, {10, 10}, {0, 10}}));
  EXPECT_EQ(v.rule, Rule::kRepeatedVertex);
  EXPECT_EQ(v.edge, 1u);
  EXPECT_EQ(v.where, (Point64{10, 0}));
  EXPECT_EQ(v.describe(), "repeated-vertex: polygon 0 edge 1 has zero length at (10 0)");
}

TEST(ValidatePolygon, LastVertexRepeatingTheFirstIsARepeatedVertex) {
  // A closed WKT-style ring: the closing edge has zero length.
  const Violation v = single(validate(Polygon{{0, 0}, {10, 0}, {10, 10}, {0, 0}}));
  EXPECT_EQ(v.rule, Rule::kRepeatedVertex);
  EXPECT_EQ(v.edge, 3u);
}

TEST(ValidatePolygon, TwoVerticesAreTooFew) {
  const Violation v = single(validate(Polygon{{0, 0}, {10, 0}}));
  EXPECT_EQ(v.rule, Rule::kTooFewVertices);
  EXPECT_EQ(v.describe(), "too-few-vertices: polygon 0 at (0 0)");
  EXPECT_EQ(single(validate(Polygon{})).rule, Rule::kTooFewVertices);
}

TEST(ValidatePolygon, CoordinateOf2To40IsOutOfRange) {
  const std::int64_t big = std::int64_t{1} << 40;
  const Violation v = single(validate(Polygon{{0, 0}, {big, 0}, {0, 10}}));
  EXPECT_EQ(v.rule, Rule::kCoordinateOutOfRange);
  EXPECT_EQ(v.edge, 1u);
  EXPECT_EQ(v.where, (Point64{big, 0}));
  EXPECT_EQ(v.describe(), "coordinate-out-of-range: polygon 0 vertex 1 at (1099511627776 0)");
}

TEST(ValidatePolygon, ExtremeInt64CoordinatesAreRejectedWithoutArithmetic) {
  // Would overflow any cross product: the ring must never reach the geometric checks.
  const std::int64_t lo = INT64_MIN, hi = INT64_MAX;
  const ValidationReport r = validate(Polygon{{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}});
  EXPECT_EQ(r.violations.size(), 4u);
  EXPECT_EQ(rules_of(r), std::set<Rule>{Rule::kCoordinateOutOfRange});
}

// --- the coordinate bound ----------------------------------------------------------------

TEST(ValidateExtremes, SquareSpanningTheWholeRangeIsValid) {
  EXPECT_TRUE(validate(square(-B, -B, B, B)).ok());
}

TEST(ValidateExtremes, OneBeyondTheBoundOnEachSide) {
  // Two corners of each square lie beyond: one violation per vertex.
  for (const Polygon& p : {square(-B, -B, B + 1, B), square(-B - 1, -B, B, B),
                           square(-B, -B, B, B + 1), square(-B, -B - 1, B, B)}) {
    const ValidationReport r = validate(p);
    EXPECT_EQ(r.violations.size(), 2u);
    EXPECT_EQ(rules_of(r), std::set<Rule>{Rule::kCoordinateOutOfRange});
  }
}

TEST(ValidateExtremes, BowTieAcrossTheWholeRange) {
  const Violation v = single(validate(Polygon{{-B, -B}, {B, B}, {B, -B}, {-B, B}}));
  EXPECT_EQ(v.rule, Rule::kSelfIntersection);
  EXPECT_EQ(v.where, (Point64{0, 0}));
}

TEST(ValidateExtremes, ClockwiseAcrossTheWholeRange) {
  EXPECT_EQ(single(validate(reversed(square(-B, -B, B, B)))).rule, Rule::kNotCounterClockwise);
}

TEST(ValidateExtremes, SliverOneUnitOffTheDiagonalIsValid) {
  // Area 2B - 1: the orientation of (B - 1, B) against the full diagonal is decided exactly.
  EXPECT_TRUE(validate(Polygon{{-B, -B}, {B, B}, {B - 1, B}}).ok());
  EXPECT_EQ(single(validate(Polygon{{-B, -B}, {B - 1, B}, {B, B}})).rule,
            Rule::kNotCounterClockwise);
}

TEST(ValidateExtremes, NotchVertexOneUnitFromTheOppositeSides) {
  // The notch reaches from (B, B) to one unit inside the opposite corner: simple. Put on the
  // bottom side instead, the notch vertex touches a non-adjacent edge.
  auto notch = [](Point64 tip) { return Polygon{{-B, -B}, {B, -B}, {B, B}, tip, {-B, B}}; };
  EXPECT_TRUE(validate(notch({-B + 1, -B + 2})).ok());
  EXPECT_TRUE(validate(notch({-B + 1, -B + 1})).ok());
  EXPECT_EQ(single(validate(notch({-B + 1, -B}))).rule, Rule::kSelfIntersection);
  EXPECT_EQ(single(validate(notch({0, -B}))).rule, Rule::kSelfIntersection);
}

TEST(ValidateExtremes, HalvesOfTheRangeAlongTheDiagonal) {
  const Polygon lower{{-B, -B}, {B, -B}, {B, B}};
  EXPECT_TRUE(validate(PolygonSet{lower, {{-B, -B}, {B, B}, {-B, B}}}).ok());
  // One unit lower at the far end: a sliver under the diagonal belongs to both.
  const Violation v = single(validate(PolygonSet{lower, {{-B, -B}, {B, B - 1}, {-B, B}}}));
  EXPECT_EQ(v.rule, Rule::kOverlappingInteriors);
  // One unit higher: the members only touch at (-B, -B).
  EXPECT_TRUE(validate(PolygonSet{lower, {{-B, -B}, {B - 1, B}, {-B, B}}}).ok());
}

TEST(ValidateExtremes, QuadrantsMeetingAtTheOriginAreValid) {
  EXPECT_TRUE(validate(PolygonSet{square(-B, -B, 0, 0), square(0, -B, B, 0), square(0, 0, B, B),
                                  square(-B, 0, 0, B)})
                  .ok());
}

// --- polygon sets ------------------------------------------------------------------------

TEST(ValidateSet, AdjacentSquaresSharingAnEdgeAreValid) {
  EXPECT_TRUE(validate(PolygonSet{square(0, 0, 10, 10), square(10, 0, 20, 10)}).ok());
  EXPECT_TRUE(validate(PolygonSet{square(0, 0, 10, 10), square(0, 10, 10, 20)}).ok());
}

TEST(ValidateSet, MembersTouchingOnlyAtAVertexAreValid) {
  EXPECT_TRUE(validate(PolygonSet{square(0, 0, 10, 10), square(10, 10, 20, 20)}).ok());
  EXPECT_TRUE(validate(PolygonSet{square(0, 0, 10, 10), square(10, -10, 20, 0)}).ok());
}

TEST(ValidateSet, VertexOnTheInteriorOfAnotherMembersEdgeIsValid) {
  EXPECT_TRUE(validate(PolygonSet{square(0, 0, 10, 10), Polygon{{10, 5}, {15, 0}, {15, 10}}}).ok());
  // A big square beside two small ones: the small ones' shared corner lies on its side.
  EXPECT_TRUE(
      validate(PolygonSet{square(0, 0, 10, 10), square(10, 0, 15, 5), square(10, 5, 15, 10)}).ok());
}

TEST(ValidateSet, FanOfTrianglesAroundOnePointIsValid) {
  EXPECT_TRUE(validate(PolygonSet{{{0, 0}, {10, 0}, {10, 10}},
                                  {{0, 0}, {10, 10}, {0, 10}},
                                  {{0, 0}, {0, 10}, {-10, 0}},
                                  {{0, 0}, {-10, 0}, {0, -10}},
                                  {{0, 0}, {0, -10}, {10, 0}}})
                  .ok());
}

TEST(ValidateSet, SquareFillingTheHoleOfARingOfRectanglesIsValid) {
  // Thesis 3.6.3, fig. 38: a region split into simple polygons with no space between them.
  EXPECT_TRUE(
      validate(PolygonSet{square(0, 0, 30, 10), square(20, 10, 30, 20), square(0, 20, 30, 30),
                          square(0, 10, 10, 20), square(10, 10, 20, 20)})
          .ok());
}

TEST(ValidateSet, ProperCrossingBetweenMembers) {
  const Violation v = single(validate(PolygonSet{square(0, 0, 10, 10), square(5, 5, 15, 15)}));
  EXPECT_EQ(v.rule, Rule::kOverlappingInteriors);
  EXPECT_EQ(v.polygon, 0u);
  EXPECT_EQ(v.other_polygon, 1u);
  EXPECT_EQ(v.describe().rfind("overlapping-interiors: polygon 0 edge ", 0), 0u);
}

TEST(ValidateSet, MemberNestedInsideAnotherWithoutContact) {
  const Violation v = single(validate(PolygonSet{square(0, 0, 10, 10), square(3, 3, 6, 6)}));
  EXPECT_EQ(v.rule, Rule::kOverlappingInteriors);
  EXPECT_EQ(v.polygon, 0u);
  EXPECT_EQ(v.other_polygon, 1u);
  EXPECT_EQ(v.where, (Point64{3, 3}));
}

TEST(ValidateSet, IdenticalMembers) {
  const Violation v = single(validate(PolygonSet{square(0, 0, 10, 10), square(0, 0, 10, 10)}));
  EXPECT_EQ(v.rule, Rule::kOverlappingInteriors);
  EXPECT_EQ(v.other_polygon, 1u);
}

TEST(ValidateSet, MemberInsideAnotherSharingAnEdge) {
  EXPECT_EQ(single(validate(PolygonSet{square(0, 0, 10, 10), square(0, 0, 10, 5)})).rule,
            Rule::kOverlappingInteriors);
  EXPECT_EQ(single(validate(PolygonSet{square(0, 0, 10, 10), square(2, 0, 5, 5)})).rule,
            Rule::kOverlappingInteriors);
}

TEST(ValidateSet, MemberInsideAnotherSharingAVertex) {
  EXPECT_EQ(
      single(validate(PolygonSet{square(0, 0, 10, 10), Polygon{{0, 0}, {5, 2}, {2, 5}}})).rule,
      Rule::kOverlappingInteriors);
  // The inner vertex lies on the outer edge's interior.
  EXPECT_EQ(
      single(validate(PolygonSet{square(0, 0, 10, 10), Polygon{{5, 0}, {7, 3}, {3, 3}}})).rule,
      Rule::kOverlappingInteriors);
}

TEST(ValidateSet, MembersSharingAnEdgeInTheSameDirection) {
  // Both rings run (0,0)->(10,0): both interiors lie above it.
  EXPECT_EQ(
      single(validate(PolygonSet{square(0, 0, 10, 10), Polygon{{0, 0}, {10, 0}, {5, 30}}})).rule,
      Rule::kOverlappingInteriors);
}

TEST(ValidateSet, DiamondPassingThroughAnEdgeAtTwoVertices) {
  // No edges cross: the diamond's vertices (10, 2) and (10, 8) lie on the square's right edge,
  // yet its left half is inside the square.
  const Violation v = single(
      validate(PolygonSet{square(0, 0, 10, 10), Polygon{{10, 2}, {12, 5}, {10, 8}, {8, 5}}}));
  EXPECT_EQ(v.rule, Rule::kOverlappingInteriors);
}

TEST(ValidateSet, InvalidMembersAreReportedAndLeftOutOfTheSetCheck) {
  // Member 1 is clockwise and covers member 0; only its own rule is reported.
  const ValidationReport r =
      validate(PolygonSet{square(0, 0, 10, 10), reversed(square(0, 0, 10, 10))});
  const Violation v = single(r);
  EXPECT_EQ(v.rule, Rule::kNotCounterClockwise);
  EXPECT_EQ(v.polygon, 1u);
}

TEST(ValidateSet, EveryOverlappingPairIsFoundUpToTheMaximum) {
  PolygonSet copies(5, square(0, 0, 10, 10));
  const ValidationReport all = validate(copies);
  EXPECT_EQ(all.violations.size(), 4u);  // each sweep drops the later member of its pair
  EXPECT_EQ(rules_of(all), std::set<Rule>{Rule::kOverlappingInteriors});
  EXPECT_EQ(validate(copies, 2).violations.size(), 2u);
  EXPECT_EQ(validate(copies, 0).violations.size(), 1u);  // never reports an invalid set as ok
}

TEST(ValidateRuleName, NamesAreStable) {
  EXPECT_STREQ(rule_name(Rule::kTooFewVertices), "too-few-vertices");
  EXPECT_STREQ(rule_name(Rule::kCoordinateOutOfRange), "coordinate-out-of-range");
  EXPECT_STREQ(rule_name(Rule::kRepeatedVertex), "repeated-vertex");
  EXPECT_STREQ(rule_name(Rule::kSelfIntersection), "self-intersection");
  EXPECT_STREQ(rule_name(Rule::kSpike), "spike");
  EXPECT_STREQ(rule_name(Rule::kNotCounterClockwise), "not-counter-clockwise");
  EXPECT_STREQ(rule_name(Rule::kOverlappingInteriors), "overlapping-interiors");
  EXPECT_STREQ(rule_name(Rule::kInvertedBox), "inverted-box");
}

}  // namespace
}  // namespace edgeland
