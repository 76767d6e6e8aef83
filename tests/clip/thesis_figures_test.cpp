// Named cases for the thesis figures that describe a clipping situation (chapter 3, figs. 17,
// 18, 21-22, 25-28, 32-33; /work/shared/seeds/000_c7d1975e78cddcea.txt). The figures are not
// reproduced coordinate for coordinate (the text does not give them); each test builds the
// situation the text describes, and its expected output was worked out by hand: exact areas
// from the shoelace formula, result polygons in the canonical form of clip.hpp (start at the
// smallest vertex, sorted), subject polygons kept apart in union (clip/README.md, Assembly),
// and, where a crossing is not an integer point, the stable snap rounding of clip/README.md
// applied by hand (derivation in the comments). Every case also passes the CGAL oracle.
#include <gtest/gtest.h>

#include "accuracy_contract.hpp"
#include "checked_clip.hpp"
#include "polygon_set_helpers.hpp"

namespace edgeland::test {
namespace {

// Runs op in checked mode, asserts the exact expected output and the contract (CGAL).
ClipResult expect_clip(ClipOp op, const char* a, const char* b, const char* expected) {
  const PolygonSet sa = parse_wkt(a), sb = parse_wkt(b);
  const Outcome o = run_clip(op, sa, sb);
  EXPECT_TRUE(o.ok()) << o.error;
  if (!o.ok()) return {};
  EXPECT_EQ(to_wkt(o.result->polygons), to_wkt(parse_wkt(expected))) << op_name(op);
  const ContractReport r = check_clip(op, sa, sb, *o.result);
  EXPECT_TRUE(r.ok()) << r.failure;
  return *o.result;
}

Int128 twice_area_of(const char* wkt) { return twice_area(parse_wkt(wkt)); }

// Fig. 17: the four operations on a subject A and a clip B that overlap in a corner.
// A = [0,4]^2, B = [2,6]^2; the crossings (4 2) and (2 4) are integer points.
// |A| = |B| = 16, |A*B| = 4, so union 28, difference 12, xor 24.
constexpr const char* kFig17A = "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))";
constexpr const char* kFig17B = "POLYGON ((2 2, 6 2, 6 6, 2 6, 2 2))";

TEST(ThesisFig17, UnionKeepsTheSubjectWholeAndAddsTheRestOfTheClip) {
  const ClipResult r = expect_clip(
      ClipOp::kUnion, kFig17A, kFig17B,
      "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((2 4, 4 4, 4 2, 6 2, 6 6, 2 6, 2 4)))");
  EXPECT_EQ(twice_area(r.polygons), 2 * 28);
  EXPECT_EQ(r.stats.vertices_snapped, 0u);
  EXPECT_EQ(r.stats.intersections, 2u);
}

TEST(ThesisFig17, IntersectionIsTheCommonSquare) {
  expect_clip(ClipOp::kIntersection, kFig17A, kFig17B, "POLYGON ((2 2, 4 2, 4 4, 2 4, 2 2))");
}

TEST(ThesisFig17, DifferenceIsAnLShape) {
  expect_clip(ClipOp::kDifference, kFig17A, kFig17B,
              "POLYGON ((0 0, 4 0, 4 2, 2 2, 2 4, 0 4, 0 0))");
  EXPECT_EQ(twice_area_of("POLYGON ((0 0, 4 0, 4 2, 2 2, 2 4, 0 4, 0 0))"), 2 * 12);
}

TEST(ThesisFig17, XorIsTwoLShapesTouchingAtTheCrossings) {
  expect_clip(ClipOp::kXor, kFig17A, kFig17B,
              "MULTIPOLYGON (((0 0, 4 0, 4 2, 2 2, 2 4, 0 4, 0 0)), "
              "((2 4, 4 4, 4 2, 6 2, 6 6, 2 6, 2 4)))");
}

// Fig. 18: the three steps of a difference. B = triangle (5 4), (9 12), (1 12) crosses the top
// edge of A = [0,10]^2 at (8 10) and (2 10) (slope 2 edges: integer crossings). A's edges
// outside B plus B's edges inside A, reversed: one polygon of area 100 - 18 = 82.
TEST(ThesisFig18, DifferenceCutsATriangularNotch) {
  const ClipResult r = expect_clip(ClipOp::kDifference, "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0))",
                                   "POLYGON ((5 4, 9 12, 1 12, 5 4))",
                                   "POLYGON ((0 0, 10 0, 10 10, 8 10, 5 4, 2 10, 0 10, 0 0))");
  EXPECT_EQ(twice_area(r.polygons), 2 * 82);
  EXPECT_EQ(r.stats.intersections, 2u);
  EXPECT_EQ(r.stats.vertices_snapped, 0u);
  EXPECT_EQ(r.stats.holes_split, 0u);
}

// Fig. 21: rounding an intersection creates a new one. A = (1 1), (4 1), (3 3); B = (4 0),
// (2 3), (3 0). Edge pq = (4 0)-(2 3) crosses ab = (1 1)-(4 1) at X = (10/3 1), close to b;
// inserting round(X) = (3 1) naively makes the new edge (3 1)-(2 3) cross A's edge ca.
// Stable snap rounding of clip/README.md by hand: the crossings (10/3 1), (8/3 1) [qr with ab]
// round to (3 1), (12/5 12/5), (9/4 9/4) [pq, qr with ca] to (2 2): hot. pq and qr meet them
// off-centre and move; ab and ca pass through the centres and stay. The routes pq -> (4 0)
// (3 1) (2 2) (2 3) and qr -> (2 3) (2 2) (3 1) (3 0) jump over no vertex (the only candidate,
// (4 1), lies on the far side of pq), so nothing else becomes hot. The part of B above (3 1)
// is then a spike that cancels: B becomes the triangle (3 0), (4 0), (3 1), touching A at
// (3 1) only. Exact: |A| = 3, |B| = 3/2, |A*B| = 71/120 (quadrilateral (8/3 1), (10/3 1),
// (12/5 12/5), (9/4 9/4)), whose perimeter exceeds 3.8: the snapped areas are within it.
constexpr const char* kFig21A = "POLYGON ((1 1, 4 1, 3 3, 1 1))";
constexpr const char* kFig21B = "POLYGON ((4 0, 2 3, 3 0, 4 0))";

TEST(ThesisFig21, SnapRoundingCreatesNoNewCrossingInIntersection) {
  const ClipResult r = expect_clip(ClipOp::kIntersection, kFig21A, kFig21B, "MULTIPOLYGON EMPTY");
  EXPECT_GT(r.stats.vertices_snapped, 0u);
  EXPECT_GT(r.stats.zero_area_dropped, 0u);  // B's collapsed spike
}

TEST(ThesisFig21, SnapRoundingCreatesNoNewCrossingInUnion) {
  expect_clip(ClipOp::kUnion, kFig21A, kFig21B,
              "MULTIPOLYGON (((1 1, 4 1, 3 3, 1 1)), ((3 0, 4 0, 3 1, 3 0)))");
}

TEST(ThesisFig21, SnapRoundingCreatesNoNewCrossingInDifference) {
  expect_clip(ClipOp::kDifference, kFig21A, kFig21B, "POLYGON ((1 1, 4 1, 3 3, 1 1))");
  expect_clip(ClipOp::kDifference, kFig21B, kFig21A, "POLYGON ((3 0, 4 0, 3 1, 3 0))");
}

TEST(ThesisFig21, SnapRoundingCreatesNoNewCrossingInXor) {
  expect_clip(ClipOp::kXor, kFig21A, kFig21B,
              "MULTIPOLYGON (((1 1, 4 1, 3 3, 1 1)), ((3 0, 4 0, 3 1, 3 0)))");
}

// Fig. 22: a narrow section of A slips past its own boundary when intersections are rounded;
// "polygon A must be split up into two polygons at position (8,4)". A = needle (0 0), (16 8),
// (0 1) of area 8, half a unit wide at x = 8; B = (8 0), (9 10), (7 10) crosses it there.
// By hand: B's edges cross A's lower edge (y = x/2) at (160/21 80/21) and (160/19 80/19), and
// A's upper edge (y = 1 + 7x/16) at (1264/167 720/167) [pixel (8 4)] and (144/17 80/17)
// [pixel (8 5)]: hot pixels (8 4), (8 5). A's lower edge passes through (8 4) itself and is
// not moved; A's upper edge meets both pixels off-centre: (16 8)(8 5)(8 4)(0 1) (no route
// jumps over a vertex, so no other pixel becomes hot). B's two long
// edges both run through (8 4) and (8 5) and collapse from (8 0) to (8 5) (cancelled); B keeps
// the triangle (8 5), (9 10), (7 10), outside A. A - B is therefore A pinched at (8 4): two
// triangles of area 4 each, touching at (8 4). Exact: |A * B| = 481280/1132761.
TEST(ThesisFig22, OneUnitSliverIsSplitAtThePinchPoint) {
  const ClipResult r = expect_clip(
      ClipOp::kDifference, "POLYGON ((0 0, 16 8, 0 1, 0 0))", "POLYGON ((8 0, 9 10, 7 10, 8 0))",
      "MULTIPOLYGON (((0 0, 8 4, 0 1, 0 0)), ((8 4, 16 8, 8 5, 8 4)))");
  EXPECT_EQ(twice_area(r.polygons), 2 * 8);
  EXPECT_GT(r.stats.zero_area_dropped, 0u);
}

// Fig. 25: all four labels. A = [0,4]^2; B = (0 0), (6 0), (6 4), (4 4), (4 2), (2 2) has a
// shared edge (0 0)-(4 0), a reverse-shared edge (4 4)-(4 2), inside edges (4 2)-(2 2)-(0 0)
// and outside edges. |A| = 16, |B| = 14, A*B = (0 0),(4 0),(4 2),(2 2) of area 6,
// B - A = [4,6]x[0,4] of area 8, A - B of area 10. No crossing is rounded.
constexpr const char* kFig25A = "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))";
constexpr const char* kFig25B = "POLYGON ((0 0, 6 0, 6 4, 4 4, 4 2, 2 2, 0 0))";

TEST(ThesisFig25, SharedAndReverseSharedEdgesInEveryOperation) {
  expect_clip(ClipOp::kUnion, kFig25A, kFig25B,
              "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((4 0, 6 0, 6 4, 4 4, 4 0)))");
  expect_clip(ClipOp::kIntersection, kFig25A, kFig25B, "POLYGON ((0 0, 4 0, 4 2, 2 2, 0 0))");
  expect_clip(ClipOp::kDifference, kFig25A, kFig25B, "POLYGON ((0 0, 2 2, 4 2, 4 4, 0 4, 0 0))");
  expect_clip(ClipOp::kDifference, kFig25B, kFig25A, "POLYGON ((4 0, 6 0, 6 4, 4 4, 4 0))");
  expect_clip(ClipOp::kXor, kFig25A, kFig25B,
              "MULTIPOLYGON (((0 0, 2 2, 4 2, 4 4, 0 4, 0 0)), ((4 0, 6 0, 6 4, 4 4, 4 0)))");
  EXPECT_EQ(twice_area_of("POLYGON ((0 0, 2 2, 4 2, 4 4, 0 4, 0 0))"), 2 * 10);
}

// Fig. 26: a unit-length edge whose midpoint rounds to an endpoint. A is an L-shape with the
// notch [3,4]x[2,3]; B = (3 3), (4 2), (6 2), (6 5), (3 5) touches A only at (4 2) and (3 3),
// and its unit edge (3 3)-(4 2) cuts the notch diagonally, leaving the triangle (3 2), (4 2),
// (3 3) between them (the "hole between polygon A and B"). That edge is outside A: B - A is
// all of B (area 17/2), with nothing added at the bottom (fig. 26b's red section), and A * B
// is empty.
constexpr const char* kFig26A = "POLYGON ((0 0, 4 0, 4 2, 3 2, 3 3, 0 3, 0 0))";
constexpr const char* kFig26B = "POLYGON ((3 3, 4 2, 6 2, 6 5, 3 5, 3 3))";

TEST(ThesisFig26, UnitEdgeBetweenTwoTouchPointsIsOutside) {
  const ClipResult r = expect_clip(ClipOp::kDifference, kFig26B, kFig26A, kFig26B);
  EXPECT_EQ(twice_area(r.polygons), 17);
  expect_clip(ClipOp::kIntersection, kFig26A, kFig26B, "MULTIPOLYGON EMPTY");
  expect_clip(ClipOp::kDifference, kFig26A, kFig26B, kFig26A);
  // The union region has a hole (the triangle), but no output polygon has one.
  expect_clip(
      ClipOp::kUnion, kFig26A, kFig26B,
      "MULTIPOLYGON (((0 0, 4 0, 4 2, 3 2, 3 3, 0 3, 0 0)), ((3 3, 4 2, 6 2, 6 5, 3 5, 3 3)))");
  expect_clip(
      ClipOp::kXor, kFig26A, kFig26B,
      "MULTIPOLYGON (((0 0, 4 0, 4 2, 3 2, 3 3, 0 3, 0 0)), ((3 3, 4 2, 6 2, 6 5, 3 5, 3 3)))");
}

// Fig. 27: labeling along A past intersections p, q (crossings) and r (a touch, where the
// labels must NOT switch). A = [0,6]^2, B = (2 -2), (4 -2), (6 2): B crosses A's bottom edge
// at p = (4 0) and q = (5 0) and touches A's right edge with its vertex r = (6 2).
// A*B = (4 0), (5 0), (6 2) of area 1; B - A = (2 -2), (4 -2), (5 0), (4 0) of area 3;
// A - B = the big polygon (0 0), (4 0), (6 2), (6 6), (0 6) of area 34 plus the corner
// triangle (5 0), (6 0), (6 2) of area 1, touching at r.
constexpr const char* kFig27A = "POLYGON ((0 0, 6 0, 6 6, 0 6, 0 0))";
constexpr const char* kFig27B = "POLYGON ((2 -2, 4 -2, 6 2, 2 -2))";

TEST(ThesisFig27, TouchingIntersectionDoesNotSwitchTheLabels) {
  expect_clip(ClipOp::kIntersection, kFig27A, kFig27B, "POLYGON ((4 0, 5 0, 6 2, 4 0))");
  const ClipResult d =
      expect_clip(ClipOp::kDifference, kFig27A, kFig27B,
                  "MULTIPOLYGON (((0 0, 4 0, 6 2, 6 6, 0 6, 0 0)), ((5 0, 6 0, 6 2, 5 0)))");
  EXPECT_EQ(twice_area(d.polygons), 2 * 35);
  expect_clip(ClipOp::kUnion, kFig27A, kFig27B,
              "MULTIPOLYGON (((0 0, 6 0, 6 6, 0 6, 0 0)), ((2 -2, 4 -2, 5 0, 4 0, 2 -2)))");
  expect_clip(ClipOp::kXor, kFig27A, kFig27B,
              "MULTIPOLYGON (((0 0, 4 0, 6 2, 6 6, 0 6, 0 0)), ((2 -2, 4 -2, 5 0, 4 0, 2 -2)), "
              "((5 0, 6 0, 6 2, 5 0)))");
}

// Fig. 28a/b: the local rule at an intersection vertex p = (2 2) that is reflex ("concave")
// for A = the L-shape (0 0),(4 0),(4 2),(2 2),(2 4),(0 4) and convex for B = (2 2), (4 0),
// (4 4); B also shares A's edge (4 0)-(4 2) (a line intersection, fig. 28b). B's edge
// p-(4 0) runs inside A, (4 4)-p outside. |A| = 12, |B| = 4,
// A*B = (2 2), (4 0), (4 2) of area 2, B - A = (2 2), (4 2), (4 4) of area 2, A - B of area 10.
constexpr const char* kFig28A = "POLYGON ((0 0, 4 0, 4 2, 2 2, 2 4, 0 4, 0 0))";
constexpr const char* kFig28B = "POLYGON ((2 2, 4 0, 4 4, 2 2))";

TEST(ThesisFig28, ReflexAndConvexCornersMeetingAtOneVertex) {
  expect_clip(ClipOp::kIntersection, kFig28A, kFig28B, "POLYGON ((2 2, 4 0, 4 2, 2 2))");
  expect_clip(ClipOp::kDifference, kFig28A, kFig28B, "POLYGON ((0 0, 4 0, 2 2, 2 4, 0 4, 0 0))");
  expect_clip(ClipOp::kDifference, kFig28B, kFig28A, "POLYGON ((2 2, 4 2, 4 4, 2 2))");
  expect_clip(ClipOp::kUnion, kFig28A, kFig28B,
              "MULTIPOLYGON (((0 0, 4 0, 4 2, 2 2, 2 4, 0 4, 0 0)), ((2 2, 4 2, 4 4, 2 2)))");
  expect_clip(ClipOp::kXor, kFig28A, kFig28B,
              "MULTIPOLYGON (((0 0, 4 0, 2 2, 2 4, 0 4, 0 0)), ((2 2, 4 2, 4 4, 2 2)))");
  EXPECT_EQ(twice_area_of("POLYGON ((0 0, 4 0, 2 2, 2 4, 0 4, 0 0))"), 2 * 10);
}

// Fig. 28a, touching only: B's convex corner fills A's reflex notch, sharing both edges at p in
// reverse: the union is two polygons, the intersection empty.
TEST(ThesisFig28, ConvexCornerInAReflexNotchOnlyTouches) {
  expect_clip(ClipOp::kIntersection, kFig28A, "POLYGON ((2 2, 5 2, 5 5, 2 5, 2 2))",
              "MULTIPOLYGON EMPTY");
  expect_clip(ClipOp::kDifference, kFig28A, "POLYGON ((2 2, 5 2, 5 5, 2 5, 2 2))", kFig28A);
}

// Figs. 32a-d: a difference whose result is two polygons (the walk restarts at an unvisited
// intersection). A = [0,10]x[0,4]; B = (4 -2), (6 -2), (10 6), (4 6) crosses it at the four
// integer points (4 0), (7 0), (9 4), (4 4). |A - B| = 40 - 16 = 24 = 16 + 8.
TEST(ThesisFig32, DifferenceSplitsTheSubjectInTwo) {
  const ClipResult r =
      expect_clip(ClipOp::kDifference, "POLYGON ((0 0, 10 0, 10 4, 0 4, 0 0))",
                  "POLYGON ((4 -2, 6 -2, 10 6, 4 6, 4 -2))",
                  "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((7 0, 10 0, 10 4, 9 4, 7 0)))");
  EXPECT_EQ(twice_area(r.polygons), 2 * 24);
  EXPECT_EQ(r.stats.intersections, 4u);
}

// Fig. 33 (and 3.6): xor, where every intersection is passed twice and the sharpest left turn
// keeps each result simple. A = a U (0 0),(6 0),(6 6),(4 6),(4 2),(2 2),(2 6),(0 6) of area
// 28; B = the bar [-1,7]x[4,5] across both arms (8 crossings). Union would enclose a hole
// (x in (2,4), y in (2,4)); no output polygon has one. |A*B| = 4, |A - B| = 24, |B - A| = 4.
constexpr const char* kFig33A = "POLYGON ((0 0, 6 0, 6 6, 4 6, 4 2, 2 2, 2 6, 0 6, 0 0))";
constexpr const char* kFig33B = "POLYGON ((-1 4, 7 4, 7 5, -1 5, -1 4))";

TEST(ThesisFig33, XorPassesEveryIntersectionTwice) {
  const ClipResult r = expect_clip(
      ClipOp::kXor, kFig33A, kFig33B,
      "MULTIPOLYGON (((-1 4, 0 4, 0 5, -1 5, -1 4)), "
      "((0 0, 6 0, 6 4, 4 4, 4 2, 2 2, 2 4, 0 4, 0 0)), ((0 5, 2 5, 2 6, 0 6, 0 5)), "
      "((2 4, 4 4, 4 5, 2 5, 2 4)), ((4 5, 6 5, 6 6, 4 6, 4 5)), ((6 4, 7 4, 7 5, 6 5, 6 4)))");
  EXPECT_EQ(twice_area(r.polygons), 2 * 28);
  EXPECT_EQ(r.stats.intersections, 8u);
}

TEST(ThesisFig33, UnionAroundAHoleKeepsEveryPolygonHoleFree) {
  const ClipResult r =
      expect_clip(ClipOp::kUnion, kFig33A, kFig33B,
                  "MULTIPOLYGON (((-1 4, 0 4, 0 5, -1 5, -1 4)), "
                  "((0 0, 6 0, 6 6, 4 6, 4 2, 2 2, 2 6, 0 6, 0 0)), ((2 4, 4 4, 4 5, 2 5, 2 4)), "
                  "((6 4, 7 4, 7 5, 6 5, 6 4)))");
  EXPECT_EQ(twice_area(r.polygons), 2 * 32);
  expect_clip(ClipOp::kIntersection, kFig33A, kFig33B,
              "MULTIPOLYGON (((0 4, 2 4, 2 5, 0 5, 0 4)), ((4 4, 6 4, 6 5, 4 5, 4 4)))");
  expect_clip(ClipOp::kDifference, kFig33A, kFig33B,
              "MULTIPOLYGON (((0 0, 6 0, 6 4, 4 4, 4 2, 2 2, 2 4, 0 4, 0 0)), "
              "((0 5, 2 5, 2 6, 0 6, 0 5)), ((4 5, 6 5, 6 6, 4 6, 4 5)))");
}

// Section 3.6: a difference with the clip strictly inside the subject makes a hole, which is
// split away by diagonals between existing vertices: the pieces are hole-free and their
// areas add up to 64 - 4 = 60.
TEST(ThesisSection36, HoleIsSplitByDiagonalsBetweenExistingVertices) {
  const PolygonSet a = parse_wkt("POLYGON ((0 0, 8 0, 8 8, 0 8, 0 0))");
  const PolygonSet b = parse_wkt("POLYGON ((3 3, 5 3, 5 5, 3 5, 3 3))");
  const Outcome o = run_clip(ClipOp::kDifference, a, b);
  ASSERT_TRUE(o.ok()) << o.error;
  EXPECT_EQ(twice_area(o.result->polygons), 2 * 60);
  EXPECT_GE(o.result->polygons.size(), 2u);
  EXPECT_EQ(o.result->stats.holes_split, 1u);
  EXPECT_EQ(o.result->stats.vertices_snapped, 0u);
  for (const Polygon& p : o.result->polygons)  // no new vertices: diagonals only
    for (const Point64& v : p)
      EXPECT_TRUE((v.x == 0 || v.x == 8 || v.x == 3 || v.x == 5) &&
                  (v.y == 0 || v.y == 8 || v.y == 3 || v.y == 5));
  const ContractReport r = check_clip(ClipOp::kDifference, a, b, *o.result);
  EXPECT_TRUE(r.ok()) << r.failure;
}

}  // namespace
}  // namespace edgeland::test
