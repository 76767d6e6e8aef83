// point_in_polygon.hpp: locate / winding_number / locate_convex / sets (thesis 2.5).
#include "edgeland/kernel/point_in_polygon.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "exact_reference.hpp"
#include "random_geometry.hpp"

namespace edgeland::test {
namespace {

using L = PointLocation;

Ring reversed(const Ring& r) { return Ring(r.rbegin(), r.rend()); }

// Both orientations must agree on the location (thesis 2.5 works for either).
void expect_location(Point64 p, const Ring& ccw, L expected) {
  EXPECT_EQ(locate(p, ccw), expected);
  EXPECT_EQ(locate(p, reversed(ccw)), expected);
}

TEST(Locate, Fig13InsideOutsideAndOnTheBorder) {
  const Ring ring{{0, 0}, {8, 0}, {8, 6}, {4, 3}, {0, 6}};
  expect_location({2, 2}, ring, L::kInside);      // p
  expect_location({4, 5}, ring, L::kOutside);     // q, in the notch
  expect_location({6, 5}, ring, L::kOutside);     // just above the notch's side
  expect_location({6, 4}, ring, L::kInside);      // just below it
  expect_location({8, 3}, ring, L::kOnBoundary);  // r
  expect_location({4, 3}, ring, L::kOnBoundary);  // a vertex
  expect_location({2, 0}, ring, L::kOnBoundary);
}

TEST(Locate, Fig15RayThroughAVertexThatDoesNotCross) {
  // a0: the ray y = 4 from (0, 4) touches the vertex (6, 4), whose neighbours are both below.
  const Ring tri{{2, 2}, {6, 0}, {6, 4}};
  expect_location({0, 4}, tri, L::kOutside);
  // a1: the ray from (1, 4) touches the bottom (5, 4) of a notch, both neighbours above,
  // then crosses the right side once.
  const Ring notched{{0, 0}, {10, 0}, {10, 10}, {7, 10}, {5, 4}, {3, 10}, {0, 10}};
  expect_location({1, 4}, notched, L::kInside);
  expect_location({-1, 4}, notched, L::kOutside);
  expect_location({5, 5}, notched, L::kOutside);
}

TEST(Locate, Fig15RayThroughAVertexThatCrosses) {
  // b: the ray y = 4 passes the vertex (8, 4) with one neighbour above and one below.
  const Ring diamond{{4, 0}, {8, 4}, {4, 8}, {0, 4}};
  expect_location({2, 4}, diamond, L::kInside);
  expect_location({-2, 4}, diamond, L::kOutside);  // through both side vertices
  expect_location({9, 4}, diamond, L::kOutside);
}

TEST(Locate, Fig15RayAlongAnEdge) {
  // c: the ray y = 4 from (0, 4) runs along the edge (6,4)-(2,4); the vertices before and
  // after the run lie on opposite sides, so the run is one crossing; then x = 10 is another.
  const Ring step{{2, 0}, {10, 0}, {10, 8}, {6, 8}, {6, 4}, {2, 4}};
  expect_location({0, 4}, step, L::kOutside);
  expect_location({8, 4}, step, L::kInside);
  expect_location({4, 4}, step, L::kOnBoundary);
  // Run with both neighbours on the same side: no crossing.
  const Ring notch{{0, 0}, {10, 0}, {10, 10}, {7, 10}, {7, 4}, {3, 4}, {3, 10}, {0, 10}};
  expect_location({1, 4}, notch, L::kInside);
  expect_location({-1, 4}, notch, L::kOutside);
  expect_location({5, 6}, notch, L::kOutside);
}

TEST(Locate, Fig26UnitEdgeMidpointIsOnlyDecidableExactly) {
  // Thesis 3.4, figure 26: polygon B's edge (4,2)-(3,3) has both endpoints on polygon A's
  // boundary, but runs through the gap outside A. Its midpoint (7/2, 5/2) is no integer
  // point: truncating it gives (3, 2), a vertex of A, and the label "touches A" is wrong.
  const Ring a{{0, 0}, {4, 0}, {4, 2}, {3, 2}, {3, 3}, {0, 3}};
  const Point64 e0{4, 2}, e1{3, 3};
  EXPECT_EQ(locate(e0, a), L::kOnBoundary);
  EXPECT_EQ(locate(e1, a), L::kOnBoundary);
  EXPECT_EQ(locate({3, 2}, a), L::kOnBoundary);  // the truncated midpoint: misleading
  const RationalPoint mid{e0.x + e1.x, e0.y + e1.y, 2};
  EXPECT_FALSE(mid.is_integer());
  // Exactly: scale A by 2 (exact in integers) and locate the doubled midpoint.
  Ring doubled;
  for (const Point64 v : a) doubled.push_back({2 * v.x, 2 * v.y});
  EXPECT_EQ(locate({e0.x + e1.x, e0.y + e1.y}, doubled), L::kOutside);
}

TEST(Locate, FullRangeSquareCornersAndNeighbours) {
  const Ring square{{-B, -B}, {B, -B}, {B, B}, {-B, B}};
  expect_location({B, B}, square, L::kOnBoundary);
  expect_location({-B, 0}, square, L::kOnBoundary);
  expect_location({B - 1, B - 1}, square, L::kInside);
  expect_location({0, 0}, square, L::kInside);
  // A thin triangle at the bound: (B-1, B) is one unit left of the long diagonal.
  const Ring thin{{-B, -B}, {B, B}, {-B, B}};
  expect_location({B - 1, B - 1}, thin, L::kOnBoundary);
  expect_location({B - 1, B}, thin, L::kOnBoundary);
  expect_location({B - 2, B - 1}, thin, L::kInside);
  expect_location({B, B - 1}, thin, L::kOutside);
}

TEST(WindingNumber, SignFollowsOrientationAndSelfIntersectionsUseNonzero) {
  const Ring square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  EXPECT_EQ(winding_number({2, 2}, square), 1);
  EXPECT_EQ(winding_number({2, 2}, reversed(square)), -1);
  EXPECT_EQ(winding_number({5, 2}, square), 0);
  // Pentagram: the core is wound around twice and is inside by the nonzero rule.
  const Ring star{{0, 10}, {-6, -8}, {10, 3}, {-10, 3}, {6, -8}};
  EXPECT_EQ(winding_number({0, 0}, star), 2);
  EXPECT_EQ(locate({0, 0}, star), L::kInside);
  // Bow-tie: the two lobes wind in opposite directions.
  const Ring bowtie{{0, 0}, {4, 4}, {4, 0}, {0, 4}};
  EXPECT_EQ(winding_number({3, 2}, bowtie), -1);
  EXPECT_EQ(winding_number({1, 2}, bowtie), 1);
  EXPECT_EQ(locate({2, 2}, bowtie), L::kOnBoundary);
}

TEST(Locate, DegenerateRingsHaveOnlyABoundary) {
  EXPECT_EQ(locate({0, 0}, Ring{}), L::kOutside);
  EXPECT_EQ(locate({1, 1}, Ring{{0, 0}, {2, 2}}), L::kOnBoundary);
  EXPECT_EQ(locate({1, 0}, Ring{{0, 0}, {2, 2}}), L::kOutside);
}

TEST(LocateConvex, CollinearVerticesAndSupportingLinesAtTheFirstVertex) {
  // v_0 = (2, 0) is a straight vertex in the middle of the bottom side; v_1 continues it.
  const Ring ring{{2, 0}, {3, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {1, 0}};
  for (const Point64 p : {Point64{2, 0}, Point64{0, 0}, Point64{4, 0}, Point64{1, 0}, Point64{4, 2},
                          Point64{2, 4}, Point64{0, 3}}) {
    EXPECT_EQ(locate_convex(p, ring), L::kOnBoundary) << p.x << ' ' << p.y;
  }
  for (const Point64 p :
       {Point64{5, 0}, Point64{-1, 0}, Point64{2, -1}, Point64{5, 5}, Point64{2, 5}}) {
    EXPECT_EQ(locate_convex(p, ring), L::kOutside) << p.x << ' ' << p.y;
  }
  EXPECT_EQ(locate_convex({2, 1}, ring), L::kInside);
  EXPECT_EQ(locate_convex({3, 3}, ring), L::kInside);
}

TEST(LocateConvex, FullRangeTriangle) {
  const Ring tri{{-B, -B}, {B, -B}, {B, B}};
  EXPECT_EQ(locate_convex({B, B - 1}, tri), L::kOnBoundary);
  EXPECT_EQ(locate_convex({B - 1, B - 1}, tri), L::kOnBoundary);
  EXPECT_EQ(locate_convex({B - 1, B - 2}, tri), L::kInside);
  EXPECT_EQ(locate_convex({B - 2, B - 1}, tri), L::kOutside);
}

TEST(LocateSet, TouchingMembersAndBoxes) {
  const PolygonSet set{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{2, 0}, {4, 0}, {4, 2}, {2, 2}}};
  std::vector<Box64> boxes;
  for (const Polygon& p : set) boxes.push_back(*bounding_box(p));
  for (const auto& [p, expected] :
       std::vector<std::pair<Point64, L>>{{{1, 1}, L::kInside},
                                          {{3, 1}, L::kInside},
                                          {{2, 1}, L::kOnBoundary},  // the shared edge
                                          {{5, 1}, L::kOutside},
                                          {{4, 2}, L::kOnBoundary}}) {
    EXPECT_EQ(locate(p, set), expected);
    EXPECT_EQ(locate(p, set, boxes), expected);
  }
  EXPECT_EQ(locate({0, 0}, PolygonSet{}), L::kOutside);
}

L ref_locate(Point64 p, const Ring& ring) {
  if (ref_on_boundary(p, ring)) return L::kOnBoundary;
  return ref_winding(p, ring) != 0 ? L::kInside : L::kOutside;
}

Point64 gen_probe(const Grid& g, const Ring& ring) {
  // Often a vertex, or a point on a vertex's row or column, where the special cases are.
  switch (*rc::gen::inRange(0, 4)) {
    case 0:
      return *rc::gen::elementOf(ring);
    case 1:
      return {gen_point(g).x, (*rc::gen::elementOf(ring)).y};
    default:
      return gen_point(g);
  }
}

RC_GTEST_PROP(LocateProperty, EqualsExactWindingReferenceOnAnyRing, ()) {
  const Grid g = gen_grid();
  const Ring ring = gen_ring(g, 10);
  const Point64 p = gen_probe(g, ring);
  const L expected = ref_locate(p, ring);
  RC_ASSERT(locate(p, ring) == expected);
  if (expected != L::kOnBoundary) RC_ASSERT(winding_number(p, ring) == ref_winding(p, ring));
}

RC_GTEST_PROP(LocateProperty, IndependentOfOrientationAndStartVertex, ()) {
  const Grid g = gen_grid();
  const Ring ring = gen_ring(g, 10);
  const Point64 p = gen_probe(g, ring);
  const auto k = *rc::gen::inRange<std::size_t>(0, ring.size());
  RC_ASSERT(locate(p, reversed(ring)) == locate(p, ring));
  RC_ASSERT(locate(p, rotated(ring, k)) == locate(p, ring));
}

RC_GTEST_PROP(LocateConvexProperty, EqualsGeneralLocate, ()) {
  const Grid g = gen_grid();
  const Ring ring = gen_convex_ring(g);
  const Point64 p = gen_probe(g, ring);
  RC_ASSERT(locate_convex(p, ring) == locate(p, ring));
}

RC_GTEST_PROP(LocateSetProperty, FirstMemberThatIsNotOutsideDecides, ()) {
  // Members here may overlap; the set version must still agree with its definition on
  // members that do not (checked per member: boundary of one, inside of one, or outside).
  const Grid g = gen_grid();
  PolygonSet set;
  const auto count = *rc::gen::inRange(0, 4);
  for (int i = 0; i < count; ++i) set.push_back(gen_star_ring(g));
  const Point64 p = gen_point(g);
  L expected = L::kOutside;
  for (const Polygon& member : set) {
    const L where = ref_locate(p, member);
    if (where != L::kOutside) {
      expected = where;
      break;
    }
  }
  std::vector<Box64> boxes;
  for (const Polygon& member : set) boxes.push_back(*bounding_box(member));
  RC_ASSERT(locate(p, set) == expected);
  RC_ASSERT(locate(p, set, boxes) == expected);
}

}  // namespace
}  // namespace edgeland::test
