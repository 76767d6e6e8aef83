// The box vocabulary of bbox.hpp and the edge normal of edge_normal.hpp, checked against their
// definitions as sets of points: every box with corners on a 4 x 4 grid, against a brute-force
// scan of the half-integer points (doubled coordinates), so each predicate is compared with
// what it claims to decide, not with another formula.
#include <gtest/gtest.h>

#include <vector>

#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/edge_normal.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/validate.hpp"

namespace edgeland {
namespace {

// Every box with 0 <= min <= max <= 3 (flat ones included).
std::vector<Box64> small_boxes() {
  std::vector<Box64> out;
  for (std::int64_t x0 = 0; x0 <= 3; ++x0)
    for (std::int64_t x1 = x0; x1 <= 3; ++x1)
      for (std::int64_t y0 = 0; y0 <= 3; ++y0)
        for (std::int64_t y1 = y0; y1 <= 3; ++y1) out.push_back({{x0, y0}, {x1, y1}});
  return out;
}

// The half-integer points of [-1, 4]^2, doubled: (2x, 2y) stands for (x, y).
std::vector<Point64> doubled_points() {
  std::vector<Point64> out;
  for (std::int64_t x = -2; x <= 8; ++x)
    for (std::int64_t y = -2; y <= 8; ++y) out.push_back({x, y});
  return out;
}

bool in_closed(const Box64& b, Point64 d) {
  return 2 * b.min.x <= d.x && d.x <= 2 * b.max.x && 2 * b.min.y <= d.y && d.y <= 2 * b.max.y;
}
bool in_open(const Box64& b, Point64 d) {
  return 2 * b.min.x < d.x && d.x < 2 * b.max.x && 2 * b.min.y < d.y && d.y < 2 * b.max.y;
}

TEST(BoxVocabulary, ContainsABoxIsContainingEveryPointOfIt) {
  const std::vector<Point64> points = doubled_points();
  for (const Box64& outer : small_boxes())
    for (const Box64& inner : small_boxes()) {
      bool all = true;
      for (Point64 d : points) all = all && (!in_closed(inner, d) || in_closed(outer, d));
      EXPECT_EQ(outer.contains(inner), all);
    }
}

TEST(BoxVocabulary, HasInteriorIsHavingAnOpenPoint) {
  const std::vector<Point64> points = doubled_points();
  for (const Box64& b : small_boxes()) {
    bool some = false;
    for (Point64 d : points) some = some || in_open(b, d);
    EXPECT_EQ(b.has_interior(), some);
  }
}

// For boxes with an interior, overlaps_open is whether the interiors share a point; overlaps
// (closed) whether the closed boxes do.
TEST(BoxVocabulary, OverlapsOpenIsSharingAnInteriorPoint) {
  const std::vector<Point64> points = doubled_points();
  for (const Box64& a : small_boxes())
    for (const Box64& b : small_boxes()) {
      bool open = false, closed = false;
      for (Point64 d : points) {
        open = open || (in_open(a, d) && in_open(b, d));
        closed = closed || (in_closed(a, d) && in_closed(b, d));
      }
      EXPECT_EQ(a.overlaps(b), closed);
      if (a.has_interior() && b.has_interior()) {
        EXPECT_EQ(a.overlaps_open(b), open);
      }
      EXPECT_EQ(a.overlaps_open(b), b.overlaps_open(a));
    }
}

// The half-open rule: p belongs to the box that holds p + eps (1, eps) for an infinitesimal
// eps > 0, so the four quadrants of [0, 4]^2 share out the points of [0, 4)^2 exactly once.
TEST(BoxVocabulary, HalfOpenBoxesOfASplitHoldEveryPointOnce) {
  const Box64 quadrants[4] = {
      {{0, 0}, {2, 2}}, {{2, 0}, {4, 2}}, {{0, 2}, {2, 4}}, {{2, 2}, {4, 4}}};
  for (std::int64_t x = -1; x <= 5; ++x)
    for (std::int64_t y = -1; y <= 5; ++y) {
      int holders = 0;
      for (const Box64& q : quadrants) holders += q.holds_half_open({x, y}) ? 1 : 0;
      const bool in_world = 0 <= x && x < 4 && 0 <= y && y < 4;
      EXPECT_EQ(holders, in_world ? 1 : 0) << x << " " << y;
    }
  // A point on the max side is not held; one on the min side is.
  EXPECT_FALSE((Box64{{0, 0}, {2, 2}}).holds_half_open({2, 1}));
  EXPECT_TRUE((Box64{{0, 0}, {2, 2}}).holds_half_open({0, 1}));
}

TEST(BoxVocabulary, BoxRingIsTheCounterClockwiseBoundaryFromMin) {
  for (const Box64& b : small_boxes()) {
    const Ring ring = box_ring(b);
    ASSERT_EQ(ring.size(), 4u);
    EXPECT_EQ(ring.front(), b.min);
    EXPECT_EQ(twice_signed_area(ring), 2 * (b.max.x - b.min.x) * (b.max.y - b.min.y));
    EXPECT_EQ(bounding_box(ring), b);
    EXPECT_EQ(validate(PolygonSet{ring}, 1).ok(), b.has_interior());
    const std::array<Point64, 4> corners = box_corners(b);
    EXPECT_EQ(Ring(corners.begin(), corners.end()), ring);
  }
}

TEST(BoxVocabulary, SegmentBoxIsTheBoxOfItsEnds) {
  for (std::int64_t ax = -2; ax <= 2; ++ax)
    for (std::int64_t ay = -2; ay <= 2; ++ay)
      for (std::int64_t bx = -2; bx <= 2; ++bx)
        for (std::int64_t by = -2; by <= 2; ++by) {
          const Segment s{{ax, ay}, {bx, by}};
          EXPECT_EQ(segment_box(s), bounding_box(Ring{s.a, s.b}));
          EXPECT_EQ(segment_box(s), segment_box(s.b, s.a));
        }
}

// Each edge of a counter-clockwise box ring: the normal is the edge turned clockwise (a right
// angle, the same length), so it points away from the box's interior.
TEST(EdgeNormal, PointsOutOfACounterClockwiseRing) {
  const Ring square = box_ring({{0, 0}, {4, 2}});
  const Point64 expected[4] = {{0, -4}, {2, 0}, {0, 4}, {-2, 0}};  // down, right, up, left
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(outward_normal(square[i], square[(i + 1) % 4]), expected[i]);
  // A slanted edge of the full range: components are differences, exact in int64.
  const Point64 a{-kCoordBound, kCoordBound}, b{kCoordBound, -kCoordBound};
  const Point64 n = outward_normal(a, b);
  EXPECT_EQ(n, (Point64{-2 * kCoordBound, -2 * kCoordBound}));
  // Perpendicular: the dot product (2^64 in each term, so in 128 bits).
  EXPECT_EQ(Int128(b.x - a.x) * n.x + Int128(b.y - a.y) * n.y, 0);
}

}  // namespace
}  // namespace edgeland
