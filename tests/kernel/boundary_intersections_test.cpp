// boundary_intersections.hpp: segment/line against a ring's boundary (thesis 2.4, 2.4.1).
#include "edgeland/kernel/boundary_intersections.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "edgeland/kernel/point_in_polygon.hpp"
#include "exact_reference.hpp"
#include "random_geometry.hpp"

namespace edgeland::test {
namespace {

using Kind = BoundaryHitKind;

const Ring kFullSquare{{-B, -B}, {B, -B}, {B, B}, {-B, B}};

TEST(BoundaryIntersections, DiagonalAcrossFullRangeDiamondCrossesAtHalfIntegers) {
  // The diamond |x| + |y| = B has its vertices on the bound; the diagonal y = x crosses it
  // at (B/2, B/2) and (-B/2, -B/2), and B is odd: exact halves, far from any integer point.
  const Ring diamond{{0, -B}, {B, 0}, {0, B}, {-B, 0}};
  const auto hits = boundary_intersections({{-B, -B}, {B, B}}, diamond);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].edge, 1u);
  EXPECT_EQ(hits[0].kind, Kind::kPoint);
  EXPECT_EQ(q(hits[0].point), (QPoint{cpp_rational(B, 2), cpp_rational(B, 2)}));
  EXPECT_EQ(hits[1].edge, 3u);
  EXPECT_EQ(q(hits[1].point), (QPoint{cpp_rational(-B, 2), cpp_rational(-B, 2)}));
  // Halves round up (predicates.hpp): B/2 -> (B + 1)/2, -B/2 -> (-B + 1)/2.
  EXPECT_EQ(round_to_grid(hits[0].point), (Point64{(B + 1) / 2, (B + 1) / 2}));
  EXPECT_EQ(round_to_grid(hits[1].point), (Point64{(-B + 1) / 2, (-B + 1) / 2}));
}

TEST(BoundaryIntersections, LineThroughOppositeCornersReportsEachVertexOnce) {
  // Thesis figure 9: half-open edges, so each vertex belongs to the edge ending there.
  const auto hits = line_boundary_intersections({{0, 0}, {1, 1}}, kFullSquare);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].edge, 1u);  // (B, B) ends edge 1
  EXPECT_EQ(q(hits[0].point), q(Point64{B, B}));
  EXPECT_EQ(hits[1].edge, 3u);  // (-B, -B) ends edge 3
  EXPECT_EQ(q(hits[1].point), q(Point64{-B, -B}));
}

TEST(BoundaryIntersections, CrossingPointIsNotAnIntegerPoint) {
  const Ring tri{{0, 0}, {3, 0}, {0, 3}};
  const auto hits = line_boundary_intersections({{0, 1}, {2, 2}}, tri);
  // y = 1 + x/2 meets the hypotenuse x + y = 3 at (4/3, 5/3), the left edge at (0, 1).
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].edge, 1u);
  EXPECT_FALSE(hits[0].point.is_integer());
  EXPECT_EQ(q(hits[0].point), (QPoint{cpp_rational(4, 3), cpp_rational(5, 3)}));
  EXPECT_EQ(hits[1].edge, 2u);
  EXPECT_EQ(q(hits[1].point), q(Point64{0, 1}));
}

TEST(BoundaryIntersections, SegmentAlongAnEdgeIsOneOverlapAndNoExtraPoint) {
  // The query runs along edge 0 from beyond v_0 to its middle: the overlap [v_0, (1, 0)] is
  // reported on edge 0; the previous edge ends at v_0 but that point is inside the overlap.
  const Ring square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  const auto hits = boundary_intersections({{-1, 0}, {1, 0}}, square);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_EQ(hits[0].edge, 0u);
  EXPECT_EQ(hits[0].kind, Kind::kOverlap);
  EXPECT_EQ(hits[0].overlap_from, (Point64{0, 0}));
  EXPECT_EQ(hits[0].overlap_to, (Point64{1, 0}));
}

TEST(BoundaryIntersections, OverlapIsOrderedAlongTheEdge) {
  const Ring square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  const auto hits = boundary_intersections({{-5, 2}, {5, 2}}, square);  // along edge 2 (-x)
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_EQ(hits[0].edge, 2u);
  EXPECT_EQ(hits[0].overlap_from, (Point64{2, 2}));
  EXPECT_EQ(hits[0].overlap_to, (Point64{0, 2}));
}

TEST(BoundaryIntersections, SuccessiveCollinearEdgesGiveSuccessiveOverlaps) {
  // Thesis 2.4.1 / figure 10: a straight vertex at (1, 0) splits the bottom side.
  const Ring ring{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}};
  const auto hits = line_boundary_intersections({{5, 0}, {6, 0}}, ring);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].edge, 0u);
  EXPECT_EQ(hits[1].edge, 1u);
  EXPECT_EQ(hits[0].overlap_to, hits[1].overlap_from);
  EXPECT_EQ(hits[1].overlap_to, (Point64{2, 0}));
  // The convex early exit finds the same.
  const auto convex = line_boundary_intersections({{5, 0}, {6, 0}}, ring, RingShape::kConvex);
  ASSERT_EQ(convex.size(), 2u);
}

TEST(BoundaryIntersections, DegenerateQueriesAndEdges) {
  const Ring ring{{0, 0}, {2, 0}, {2, 0}, {2, 2}};  // a repeated vertex
  // A degenerate query is the point itself: (2, 0) ends edge 0, the empty edge 1 reports
  // nothing, and edge 2 starts there.
  const auto hits = boundary_intersections({{2, 0}, {2, 0}}, ring);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_EQ(hits[0].edge, 0u);
  EXPECT_TRUE(line_boundary_intersections({{9, 9}, {9, 9}}, ring).empty());
  EXPECT_TRUE(boundary_intersections({{0, 1}, {1, 5}}, Ring{}).empty());
}

TEST(BoundaryIntersections, MissIsEmpty) {
  EXPECT_TRUE(boundary_intersections({{3, 3}, {4, 4}}, Ring{{0, 0}, {2, 0}, {2, 2}}).empty());
  EXPECT_TRUE(line_boundary_intersections({{0, 5}, {1, 5}}, Ring{{0, 0}, {2, 0}, {2, 2}}).empty());
}

// Checks the kernel's hits against the per-edge rational reference and the documented
// half-open rules, independently of the kernel's scan.
void check_against_reference(const Segment& query, bool line, const Ring& ring,
                             const std::vector<BoundaryHit>& hits) {
  const std::size_t n = ring.size();
  const bool line_query = line && query.a != query.b;
  std::vector<RefMeet> meet(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % n];
    if (a != b) meet[i] = ref_meet(q(query.a), q(query.b), line_query, q(a), q(b));
  }
  auto next_proper = [&](std::size_t i) {
    for (std::size_t s = 1; s < n; ++s) {
      const std::size_t j = (i + s) % n;
      if (ring[j] != ring[(j + 1) % n]) return j;
    }
    return i;
  };
  std::vector<BoundaryHit> expected;
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % n];
    if (meet[i].kind == RefMeet::kInterval) {
      BoundaryHit h;
      h.edge = i;
      h.kind = Kind::kOverlap;
      expected.push_back(h);
    } else if (meet[i].kind == RefMeet::kPoint) {
      if (meet[i].a == q(a)) continue;  // half-open: not the start vertex
      if (meet[i].a == q(b) && meet[next_proper(i)].kind == RefMeet::kInterval) continue;
      BoundaryHit h;
      h.edge = i;
      h.kind = Kind::kPoint;
      expected.push_back(h);
    }
  }
  RC_ASSERT(hits.size() == expected.size());
  for (std::size_t k = 0; k < hits.size(); ++k) {
    const BoundaryHit& h = hits[k];
    RC_ASSERT(h.edge == expected[k].edge);
    RC_ASSERT(h.kind == expected[k].kind);
    const RefMeet& m = meet[h.edge];
    if (h.kind == Kind::kPoint) {
      RC_ASSERT(h.point.den > 0);
      RC_ASSERT(q(h.point) == m.a);
    } else {
      RC_ASSERT(q(h.overlap_from) == m.a);
      RC_ASSERT(q(h.overlap_to) == m.b);
    }
  }
}

Segment gen_query(const Grid& g, const Ring& ring) {
  // Often through a vertex or along an edge, where the special cases are.
  switch (*rc::gen::inRange(0, 4)) {
    case 0:
      return {*rc::gen::elementOf(ring), gen_point(g)};
    case 1: {
      const std::size_t i = *rc::gen::inRange<std::size_t>(0, ring.size());
      return {ring[i], ring[(i + 1) % ring.size()]};
    }
    default:
      return {gen_point(g), gen_point(g)};
  }
}

RC_GTEST_PROP(BoundaryIntersectionsProperty, SegmentMatchesRationalReference, ()) {
  const Grid g = gen_grid();
  const Ring ring = gen_ring(g);
  const Segment s = gen_query(g, ring);
  check_against_reference(s, false, ring, boundary_intersections(s, ring));
}

RC_GTEST_PROP(BoundaryIntersectionsProperty, LineMatchesRationalReference, ()) {
  const Grid g = gen_grid();
  const Ring ring = gen_ring(g);
  const Segment s = gen_query(g, ring);
  check_against_reference(s, true, ring, line_boundary_intersections(s, ring));
}

bool same_hits(const std::vector<BoundaryHit>& a, const std::vector<BoundaryHit>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].edge != b[i].edge || a[i].kind != b[i].kind) return false;
    if (a[i].kind == Kind::kPoint && !(q(a[i].point) == q(b[i].point))) return false;
    if (a[i].kind == Kind::kOverlap &&
        (a[i].overlap_from != b[i].overlap_from || a[i].overlap_to != b[i].overlap_to)) {
      return false;
    }
  }
  return true;
}

RC_GTEST_PROP(BoundaryIntersectionsProperty, ConvexEarlyExitFindsEverything, ()) {
  const Grid g = gen_grid();
  const Ring ring = gen_convex_ring(g);
  const Segment s = gen_query(g, ring);
  RC_ASSERT(same_hits(boundary_intersections(s, ring, RingShape::kConvex),
                      boundary_intersections(s, ring)));
  RC_ASSERT(same_hits(line_boundary_intersections(s, ring, RingShape::kConvex),
                      line_boundary_intersections(s, ring)));
}

// On a simple ring no point of the boundary is reported twice: point hits are distinct and
// none lies inside a reported overlap.
RC_GTEST_PROP(BoundaryIntersectionsProperty, SimpleRingReportsEachPointOnce, ()) {
  const Grid g = gen_grid();
  const Ring ring = gen_star_ring(g);
  const Segment s = gen_query(g, ring);
  for (const bool line : {false, true}) {
    const auto hits = line ? line_boundary_intersections(s, ring) : boundary_intersections(s, ring);
    for (std::size_t i = 0; i < hits.size(); ++i) {
      if (hits[i].kind != Kind::kPoint) continue;
      for (std::size_t j = 0; j < hits.size(); ++j) {
        if (i == j) continue;
        if (hits[j].kind == Kind::kPoint) {
          RC_ASSERT(!(q(hits[i].point) == q(hits[j].point)));
        } else {
          RC_ASSERT(
              !ref_on_segment(q(hits[i].point), q(hits[j].overlap_from), q(hits[j].overlap_to)));
        }
      }
    }
  }
}

}  // namespace
}  // namespace edgeland::test
