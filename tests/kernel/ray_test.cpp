// ray.hpp: first hit of a ray, back-face culling, convex early exit (thesis 2.4.1, 2.4.2).
#include "edgeland/kernel/ray.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "edgeland/kernel/point_in_polygon.hpp"
#include "exact_reference.hpp"
#include "random_geometry.hpp"
#include "support/big_int.hpp"

namespace edgeland::test {
namespace {

constexpr std::int64_t D = kMaxRayDirection;
const Ring kSquare{{0, 0}, {2, 0}, {2, 2}, {0, 2}};

cpp_rational value(const Fraction& f) { return cpp_rational(big(f.num), big(f.den)); }

TEST(FirstHit, LongestDirectionIntoFullRangeDiamond) {
  // From the corner (-B, -B) along (2B+1, 2B+1): the diamond |x| + |y| = B is entered at
  // (-B/2, -B/2), i.e. t = (B/2) / (2B+1).
  const Ring diamond{{0, -B}, {B, 0}, {0, B}, {-B, 0}};
  for (const RayCulling c : {RayCulling::kNoCulling, RayCulling::kOriginOutside}) {
    const auto hit = first_hit({{-B, -B}, D, D}, diamond, c);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->edge, 3u);
    EXPECT_EQ(value(hit->t), cpp_rational(B, 2 * D));
    EXPECT_EQ(q(hit->point), (QPoint{cpp_rational(-B, 2), cpp_rational(-B, 2)}));
  }
}

TEST(FirstHit, ThroughAVertexReportsTheLowerEdge) {
  const auto hit = first_hit({{-1, -1}, 1, 1}, kSquare);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->edge, 0u);  // (0, 0) is shared by edges 3 and 0
  EXPECT_EQ(value(hit->t), 1);
  EXPECT_EQ(q(hit->point), q(Point64{0, 0}));
}

TEST(FirstHit, AlongAnEdgeHitsWhereItFirstTouches) {
  // Thesis figure 15 (c) for rays: the contact is a segment; its nearest point counts.
  const auto hit = first_hit({{-2, 0}, 1, 0}, kSquare);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->edge, 0u);
  EXPECT_EQ(value(hit->t), 2);
  const auto from_inside_edge = first_hit({{1, 0}, 3, 0}, kSquare);
  ASSERT_TRUE(from_inside_edge.has_value());
  EXPECT_EQ(value(from_inside_edge->t), 0);  // the origin is on edge 0
}

TEST(FirstHit, MissIsNullopt) {
  EXPECT_FALSE(first_hit({{3, 3}, 1, 0}, kSquare).has_value());
  EXPECT_FALSE(first_hit({{1, 1}, 0, 0}, kSquare).has_value());  // zero direction, inside
  const auto on_edge = first_hit({{1, 0}, 0, 0}, kSquare);       // zero direction, on edge
  ASSERT_TRUE(on_edge.has_value());
  EXPECT_EQ(on_edge->edge, 0u);
}

TEST(FirstHit, CullingSkipsFacesAsDocumented) {
  // Thesis figure 11: from outside only front faces matter, from inside only back faces.
  const Ray from_outside{{-1, 1}, 1, 0};
  const Ray from_inside{{1, 1}, 1, 0};
  EXPECT_EQ(first_hit(from_outside, kSquare, RayCulling::kOriginOutside)->edge, 3u);
  EXPECT_EQ(first_hit(from_inside, kSquare, RayCulling::kOriginInside)->edge, 1u);
  // Misused modes skip the edge the ray really meets first.
  const auto wrong_inside = first_hit(from_outside, kSquare, RayCulling::kOriginInside);
  ASSERT_TRUE(wrong_inside.has_value());
  EXPECT_EQ(wrong_inside->edge, 1u);
  EXPECT_EQ(value(wrong_inside->t), 3);
  EXPECT_FALSE(first_hit(from_inside, kSquare, RayCulling::kOriginOutside).has_value());
}

TEST(FirstHit, ConvexEarlyExitOnALargeConvexRing) {
  // A convex ring with many vertices (points on the parabola y = x^2), entered early.
  Ring ring;
  for (std::int64_t x = -200; x <= 200; ++x) ring.push_back({x, x * x});
  const Ray ray{{-300, 10}, 1, 0};
  const auto full = first_hit(ray, ring, RayCulling::kOriginOutside);
  const auto fast = first_hit(ray, ring, RayCulling::kOriginOutside, RingShape::kConvex);
  ASSERT_TRUE(full && fast);
  EXPECT_EQ(full->edge, fast->edge);
  EXPECT_EQ(value(full->t), value(fast->t));
  // Enters x^2 = 10 at x = -sqrt(10), between x = -4 and x = -3 (edge from vertex 196).
  EXPECT_EQ(fast->edge, 196u);
}

// Reference: for each edge not culled (by the exact sign of cross(d, e)), the contact of
// the closed edge with the ray's line (rational reference), restricted to t >= 0.
struct RefHit {
  std::size_t edge;
  cpp_rational t;
};

std::optional<RefHit> ref_first_hit(const Ray& ray, const Ring& ring, RayCulling culling) {
  std::optional<RefHit> best;
  const QPoint o = q(ray.origin), d{cpp_rational(ray.dx), cpp_rational(ray.dy)};
  const cpp_rational dd = dot(d, d);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % ring.size()];
    const int face =
        sgn(ref_cross(cpp_int(ray.dx), cpp_int(ray.dy), cpp_int(b.x) - a.x, cpp_int(b.y) - a.y));
    if (culling == RayCulling::kOriginOutside && face > 0) continue;
    if (culling == RayCulling::kOriginInside && face < 0) continue;
    std::optional<cpp_rational> t;
    if (dd == 0) {
      if (ref_on_segment(o, q(a), q(b))) t = 0;
    } else {
      const QPoint far{o.x + d.x, o.y + d.y};
      const RefMeet m = ref_meet(o, far, true, q(a), q(b));
      auto param = [&](const QPoint& x) { return dot(x - o, d) / dd; };
      if (m.kind == RefMeet::kPoint && param(m.a) >= 0) t = param(m.a);
      if (m.kind == RefMeet::kInterval) {
        cpp_rational lo = param(m.a), hi = param(m.b);
        if (hi < lo) std::swap(lo, hi);
        if (hi >= 0) t = lo < 0 ? cpp_rational(0) : lo;
      }
    }
    if (t && (!best || *t < best->t)) best = RefHit{i, *t};
  }
  return best;
}

Ray gen_ray(const Grid& g, const Ring& ring) {
  const Point64 o = gen_point(g);
  std::int64_t dx = 0, dy = 0;
  switch (*rc::gen::inRange(0, 4)) {
    case 0: {  // towards a vertex: rays through vertices
      const Point64 v = *rc::gen::elementOf(ring);
      dx = v.x - o.x;
      dy = v.y - o.y;
      break;
    }
    case 1: {  // parallel to an edge: rays along edges
      const std::size_t i = *rc::gen::inRange<std::size_t>(0, ring.size());
      const Point64 a = ring[i], b = ring[(i + 1) % ring.size()];
      dx = b.x - a.x;
      dy = b.y - a.y;
      break;
    }
    case 2:
      dx = *rc::gen::inRange<std::int64_t>(-3, 4);
      dy = *rc::gen::inRange<std::int64_t>(-3, 4);
      break;
    default:
      dx = *rc::gen::inRange<std::int64_t>(-D, D + 1);
      dy = *rc::gen::element<std::int64_t>(-D, D, *rc::gen::inRange<std::int64_t>(-D, D + 1));
      break;
  }
  return {o, dx, dy};
}

RayCulling gen_culling() {
  return *rc::gen::element(RayCulling::kNoCulling, RayCulling::kOriginOutside,
                           RayCulling::kOriginInside);
}

void check_same(const std::optional<RayHit>& a, const std::optional<RayHit>& b) {
  RC_ASSERT(a.has_value() == b.has_value());
  if (!a) return;
  RC_ASSERT(a->edge == b->edge);
  RC_ASSERT(compare(a->t, b->t) == 0);
}

RC_GTEST_PROP(FirstHitProperty, MatchesRationalReference, ()) {
  const Grid g = gen_grid();
  const Ring ring = gen_ring(g);
  const Ray ray = gen_ray(g, ring);
  const RayCulling culling = gen_culling();
  const auto hit = first_hit(ray, ring, culling);
  const auto ref = ref_first_hit(ray, ring, culling);
  RC_ASSERT(hit.has_value() == ref.has_value());
  if (!hit) return;
  RC_ASSERT(hit->edge == ref->edge);
  RC_ASSERT(hit->t.den > 0);
  RC_ASSERT(value(hit->t) == ref->t);
  const QPoint expected{cpp_rational(ray.origin.x) + ref->t * ray.dx,
                        cpp_rational(ray.origin.y) + ref->t * ray.dy};
  RC_ASSERT(q(hit->point) == expected);
}

// Thesis 2.4.2: culling drops only edges that cannot hold the first hit, when the origin is
// strictly on the side the mode names (simple counter-clockwise rings).
RC_GTEST_PROP(FirstHitProperty, CullingKeepsTheFirstHitOfSimpleRings, ()) {
  const Grid g = gen_grid();
  const Ring ring = gen_star_ring(g);
  const Ray ray = gen_ray(g, ring);
  const PointLocation where = locate(ray.origin, ring);
  RC_PRE(where != PointLocation::kOnBoundary);
  const RayCulling mode =
      where == PointLocation::kOutside ? RayCulling::kOriginOutside : RayCulling::kOriginInside;
  const auto all = first_hit(ray, ring);
  const auto culled = first_hit(ray, ring, mode);
  RC_ASSERT(all.has_value() == culled.has_value());
  if (all) RC_ASSERT(compare(all->t, culled->t) == 0);
}

RC_GTEST_PROP(FirstHitProperty, ConvexEarlyExitEqualsFullScan, ()) {
  const Grid g = gen_grid();
  const Ring ring = gen_convex_ring(g);
  const Ray ray = gen_ray(g, ring);
  const RayCulling culling = gen_culling();
  check_same(first_hit(ray, ring, culling, RingShape::kConvex), first_hit(ray, ring, culling));
}

// The reference's contact of the ray with one closed segment: first_hit's reference on the
// two-vertex ring a -> b -> a, whose two edges are the segment.
std::optional<cpp_rational> ref_contact(const Ray& ray, const Segment& e) {
  const auto hit = ref_first_hit(ray, Ring{e.a, e.b}, RayCulling::kNoCulling);
  if (!hit) return std::nullopt;
  return hit->t;
}

// Half of the rays along an axis (the probes of the clipper, which take ray_contact's fast
// rejection), the other half as gen_ray makes them.
Ray gen_probe_ray(const Grid& g, const Ring& near) {
  Ray ray = gen_ray(g, near);
  if (*rc::gen::arbitrary<bool>()) {
    const std::int64_t length = *rc::gen::element<std::int64_t>(1, 2, 7, D);
    switch (*rc::gen::inRange(0, 4)) {
      case 0:
        ray.dx = length, ray.dy = 0;
        break;
      case 1:
        ray.dx = -length, ray.dy = 0;
        break;
      case 2:
        ray.dx = 0, ray.dy = length;
        break;
      default:
        ray.dx = 0, ray.dy = -length;
        break;
    }
  }
  return ray;
}

RC_GTEST_PROP(RayContactProperty, MatchesRationalReference, ()) {
  const Grid g = gen_grid();
  const Segment e{gen_point(g), gen_point(g)};
  const Ray ray = gen_probe_ray(g, Ring{e.a, e.b});
  const auto t = ray_contact(ray, e);
  const auto ref = ref_contact(ray, e);
  RC_ASSERT(t.has_value() == ref.has_value());
  if (!t) return;
  RC_ASSERT(t->den > 0);
  RC_ASSERT(value(*t) == *ref);
  const QPoint expected{cpp_rational(ray.origin.x) + *ref * ray.dx,
                        cpp_rational(ray.origin.y) + *ref * ray.dy};
  RC_ASSERT(q(ray_point(ray, *t)) == expected);
}

// Offers report missed / farther / nearest exactly as the reference contacts say, the hit is
// the smallest contact, and among equal contacts the first offered stays the hit.
RC_GTEST_PROP(NearestHitProperty, KeepsTheFirstOfTheNearestContacts, ()) {
  const Grid g = gen_grid();
  const std::vector<Point64> ends = gen_points(g, 2, 16);
  const Ray ray = gen_probe_ray(g, ends);
  NearestHit nearest(ray);
  std::optional<cpp_rational> best;
  for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
    const Segment e{ends[i], ends[i + 1]};
    const std::optional<cpp_rational> t = ref_contact(ray, e);
    const NearestHit::Offer expected = !t                    ? NearestHit::Offer::kMissed
                                       : best && *t >= *best ? NearestHit::Offer::kFarther
                                                             : NearestHit::Offer::kNearest;
    RC_ASSERT(nearest.offer(e) == expected);
    if (expected == NearestHit::Offer::kNearest) best = t;
  }
  RC_ASSERT(nearest.found() == best.has_value());
  if (!best) return;
  RC_ASSERT(value(nearest.t()) == *best);
  const QPoint expected{cpp_rational(ray.origin.x) + *best * ray.dx,
                        cpp_rational(ray.origin.y) + *best * ray.dy};
  RC_ASSERT(q(nearest.point()) == expected);
}

TEST(NearestHit, WestwardProbeMeetsTheNearestEdgeAndEndsAreVertices) {
  // From (10, 0) towards -x: a vertical edge at x = 4, a vertex at (6, 0) of an edge leaving the
  // line, a horizontal edge on the line from x = 1 to 3 (met at its nearer end, 3), and an edge
  // behind the origin. The vertex at x = 6 is nearest (t = 4).
  NearestHit west(Ray{{10, 0}, -1, 0});
  EXPECT_EQ(west.offer({{4, -5}, {4, 5}}), NearestHit::Offer::kNearest);
  EXPECT_EQ(west.offer({{12, -1}, {12, 1}}), NearestHit::Offer::kMissed);
  EXPECT_EQ(west.offer({{1, 0}, {3, 0}}), NearestHit::Offer::kFarther);
  EXPECT_EQ(west.offer({{6, 0}, {8, 9}}), NearestHit::Offer::kNearest);
  EXPECT_EQ(west.offer({{6, 0}, {5, -9}}), NearestHit::Offer::kFarther);  // same point: first stays
  ASSERT_TRUE(west.found());
  EXPECT_EQ(compare(west.t(), Fraction{4, 1}), 0);
  EXPECT_TRUE(is_exactly(west.point(), {6, 0}));
  EXPECT_FALSE(is_exactly(west.point(), {6, 1}));
}

TEST(NearestHit, AnOpenRayPassesOverSegmentsThroughItsOrigin) {
  // From (0, 0) downwards: a segment through the origin, one ending at it, one along the ray
  // starting at it, and a horizontal one at y = -3. Closed, the first three are met at t = 0;
  // open, only the last is met.
  const Segment through{{-1, 1}, {1, -1}}, ending{{0, 0}, {4, -4}}, along{{0, 0}, {0, -9}};
  const Segment below{{-5, -3}, {5, -3}};
  NearestHit closed(Ray{{0, 0}, 0, -1});
  NearestHit open(Ray{{0, 0}, 0, -1}, NearestHit::Origin::kExcluded);
  for (const Segment& e : {through, ending, along}) {
    closed.offer(e);
    EXPECT_EQ(open.offer(e), NearestHit::Offer::kMissed);
  }
  EXPECT_EQ(compare(closed.t(), Fraction{0, 1}), 0);
  EXPECT_FALSE(open.found());
  EXPECT_EQ(open.offer(below), NearestHit::Offer::kNearest);
  EXPECT_TRUE(is_exactly(open.point(), {0, -3}));
}

}  // namespace
}  // namespace edgeland::test
