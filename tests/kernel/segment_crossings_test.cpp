// segment_crossings, inside_half_open and the box queries (segment_crossings.hpp,
// point_in_polygon.hpp, box_queries.hpp) against references written from the definitions in
// exact rationals: the segment and the point really moved by eps (1, eps) for a tiny rational
// eps, winding numbers of rational points, Liang-Barsky clipping, and the area of a ring clipped
// to a box by Sutherland-Hodgman (right for any simple ring against a convex window).
#include "edgeland/kernel/segment_crossings.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "edgeland/kernel/box_queries.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/validate.hpp"
#include "exact_reference.hpp"
#include "random_geometry.hpp"
#include "support/big_int.hpp"

namespace edgeland::test {
namespace {

cpp_rational tiny(int exponent) { return cpp_rational(cpp_int(1), cpp_int(1) << exponent); }

// Winding number of the ring around a rational point that lies on no edge.
int ref_winding(const Ring& ring, const QPoint& p) {
  int w = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const QPoint a = q(ring[i]), b = q(ring[(i + 1) % n]);
    const cpp_rational side = ref_cross(b - a, p - a);
    if (a.y <= p.y) {
      if (b.y > p.y && side > 0) ++w;
    } else if (b.y <= p.y && side < 0) {
      --w;
    }
  }
  return w;
}

// The point moved by (eps, eps^2): eps = 2^-200 lies far below any gap between the rational
// points these tests meet (coordinates within 2^31, parameters with denominators below 2^70).
QPoint moved(const QPoint& p) {
  const cpp_rational eps = tiny(200);
  return {p.x + eps, p.y + eps * eps};
}

cpp_rational as_rational(const Fraction& f) { return cpp_rational(big(f.num), big(f.den)); }

QPoint at(const Segment& s, const cpp_rational& t) {
  return {s.a.x + t * (cpp_int(s.b.x) - s.a.x), s.a.y + t * (cpp_int(s.b.y) - s.a.y)};
}

// Every parameter where the line of s meets a vertex or the line of an edge, within [0, 1].
std::vector<cpp_rational> candidates(const Segment& s, const Ring& ring) {
  const QPoint a = q(s.a), d = q(s.b) - a;
  std::vector<cpp_rational> ts{0, 1};
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const QPoint u = q(ring[i]), e = q(ring[(i + 1) % n]) - u;
    if (ref_cross(d, u - a) == 0) ts.push_back(dot(u - a, d) / dot(d, d));
    if (ref_cross(d, e) != 0) ts.push_back(ref_cross(u - a, e) / ref_cross(d, e));
  }
  std::vector<cpp_rational> kept;
  for (const cpp_rational& t : ts)
    if (t >= 0 && t <= 1) kept.push_back(t);
  std::sort(kept.begin(), kept.end());
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  return kept;
}

struct RefCrossing {
  cpp_rational t;
  bool entering;
};

// The changes of inside / outside along the moved segment, and the status just before t = 0.
std::vector<RefCrossing> ref_crossings(const Segment& s, const Ring& ring, bool& inside_before) {
  const std::vector<cpp_rational> ts = candidates(s, ring);
  const cpp_rational eta = tiny(100);
  auto inside = [&](const cpp_rational& t) { return ref_winding(ring, moved(at(s, t))) != 0; };
  inside_before = inside(-eta);
  bool prev = inside_before;
  std::vector<RefCrossing> out;
  for (std::size_t k = 0; k < ts.size(); ++k) {
    const bool now = inside(k + 1 < ts.size() ? (ts[k] + ts[k + 1]) / 2 : cpp_rational(1) + eta);
    if (now != prev) out.push_back({ts[k], now});
    prev = now;
  }
  return out;
}

// Whether a simple ring from the generators is counter-clockwise and valid; made so if it can be.
std::optional<Ring> valid_ccw(Ring r) {
  if (validate(r, 1).ok()) return r;
  std::reverse(r.begin(), r.end());
  if (validate(r, 1).ok()) return r;
  return std::nullopt;
}

TEST(SegmentCrossings, DegenerateContactsFollowTheMovedSegment) {
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  // Along the bottom edge, eastwards: the moved segment runs just above it, inside.
  RingCrossings r = segment_crossings({{-5, 0}, {5, 0}}, square);
  ASSERT_EQ(r.crossings.size(), 1u);
  EXPECT_TRUE(r.crossings[0].entering);
  EXPECT_TRUE(r.crossings[0].at_vertex);
  EXPECT_EQ(compare(r.crossings[0].t, Fraction{1, 2}), 0);
  // Along the top edge: just above it, outside: no crossing at all.
  EXPECT_TRUE(segment_crossings({{-5, 10}, {15, 10}}, square).crossings.empty());
  // Through the corner (0, 0) diagonally: in at the corner, out at (10, 10).
  r = segment_crossings({{-5, -5}, {15, 15}}, square);
  ASSERT_EQ(r.crossings.size(), 2u);
  EXPECT_TRUE(r.crossings[0].entering);
  EXPECT_FALSE(r.crossings[1].entering);
  EXPECT_EQ(crossing_point({{-5, -5}, {15, 15}}, square, r.crossings[1]),
            (RationalPoint{10, 10, 1}));
  // Starting inside: counted from the crossings before t = 0.
  r = segment_crossings({{5, 5}, {20, 5}}, square);
  EXPECT_TRUE(r.inside_before);
  ASSERT_EQ(r.crossings.size(), 1u);
  EXPECT_FALSE(r.crossings[0].entering);
  // Culling back faces keeps only the way in.
  EXPECT_TRUE(
      segment_crossings({{5, 5}, {20, 5}}, square, CrossingCulling::kBackFaces).crossings.empty());
}

TEST(InsideHalfOpen, PointsOnTheBoundaryBelongToTheFaceNorthEastOfThem) {
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  EXPECT_TRUE(inside_half_open({0, 0}, square));
  EXPECT_TRUE(inside_half_open({0, 5}, square));
  EXPECT_TRUE(inside_half_open({5, 0}, square));
  EXPECT_FALSE(inside_half_open({10, 5}, square));
  EXPECT_FALSE(inside_half_open({5, 10}, square));
  EXPECT_FALSE(inside_half_open({10, 10}, square));
  EXPECT_TRUE(inside_half_open({9, 9}, square));
}

TEST(BoxQueries, TouchingIsNotOverlapping) {
  const Box64 box{{0, 0}, {10, 10}};
  EXPECT_FALSE(segment_meets_open_box({{0, -5}, {0, 15}}, box));  // along a side
  EXPECT_FALSE(segment_meets_open_box({{-5, 5}, {5, -5}}, box));  // through a corner only
  EXPECT_TRUE(segment_meets_open_box({{-5, 6}, {6, -5}}, box));
  const Ring outside{{10, 0}, {20, 0}, {20, 10}, {10, 10}};
  EXPECT_FALSE(interiors_overlap(box, outside));
  const Ring around{{-5, -5}, {15, -5}, {15, 15}, {-5, 15}};
  EXPECT_TRUE(interiors_overlap(box, around));
  const auto range = clip_parameters({{-10, 5}, {30, 5}}, box);
  ASSERT_TRUE(range.has_value());
  EXPECT_EQ(compare(range->t0, Fraction{1, 4}), 0);
  EXPECT_EQ(compare(range->t1, Fraction{1, 2}), 0);
  EXPECT_FALSE(clip_parameters({{-10, 11}, {30, 11}}, box).has_value());
}

RC_GTEST_PROP(SegmentCrossingsProperty, AgreesWithTheMovedSegment, ()) {
  const Grid g = gen_grid();
  const auto ring = valid_ccw(*rc::gen::element(0, 1) == 0 ? gen_star_ring(g) : gen_convex_ring(g));
  RC_PRE(ring.has_value());
  const Segment s{gen_point(g), gen_point(g)};
  RC_PRE(s.a != s.b);
  bool want_before = false;
  const std::vector<RefCrossing> want = ref_crossings(s, *ring, want_before);
  const RingCrossings got = segment_crossings(s, *ring);
  RC_ASSERT(got.inside_before == want_before);
  // Crossings at one parameter (the tip of a vertex) come in pairs the reference does not see.
  std::vector<SegmentCrossing> net;
  for (std::size_t i = 0; i < got.crossings.size();) {
    std::size_t j = i + 1;
    while (j < got.crossings.size() && compare(got.crossings[j].t, got.crossings[i].t) == 0) ++j;
    int count = 0;
    for (std::size_t k = i; k < j; ++k) count += got.crossings[k].entering ? 1 : -1;
    if (count != 0) net.push_back(got.crossings[i]), net.back().entering = count > 0;
    i = j;
  }
  RC_ASSERT(net.size() == want.size());
  for (std::size_t i = 0; i < net.size(); ++i) {
    RC_ASSERT(as_rational(net[i].t) == want[i].t);
    RC_ASSERT(net[i].entering == want[i].entering);
  }
  for (const SegmentCrossing& c : got.crossings) {
    const QPoint p = q(crossing_point(s, *ring, c));
    RC_ASSERT(p == at(s, as_rational(c.t)));
  }
  // Culling back faces lists exactly the entering crossings.
  const RingCrossings culled = segment_crossings(s, *ring, CrossingCulling::kBackFaces, false);
  std::size_t entering = 0;
  for (const SegmentCrossing& c : got.crossings) entering += c.entering ? 1 : 0;
  RC_ASSERT(culled.crossings.size() == entering);
}

RC_GTEST_PROP(InsideHalfOpenProperty, IsTheWindingAtThePointMoved, ()) {
  const Grid g = gen_grid();
  const Ring ring = gen_ring(g);
  const Point64 p = *rc::gen::element(0, 1) == 0
                        ? ring[*rc::gen::inRange<std::size_t>(0, ring.size())]
                        : gen_point(g);
  RC_ASSERT(inside_half_open(p, ring) == (ref_winding(ring, moved(q(p))) != 0));
}

// Liang-Barsky on rationals: the parameters of s inside the closed (or open) box.
std::optional<std::pair<cpp_rational, cpp_rational>> ref_clip(const Segment& s, const Box64& b,
                                                              bool open) {
  cpp_rational t0 = 0, t1 = 1;
  const cpp_int d[2] = {cpp_int(s.b.x) - s.a.x, cpp_int(s.b.y) - s.a.y};
  const cpp_int a[2] = {s.a.x, s.a.y}, lo[2] = {b.min.x, b.min.y}, hi[2] = {b.max.x, b.max.y};
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0) {
      if (open ? (a[k] <= lo[k] || a[k] >= hi[k]) : (a[k] < lo[k] || a[k] > hi[k]))
        return std::nullopt;
      continue;
    }
    cpp_rational u = cpp_rational(lo[k] - a[k]) / d[k], v = cpp_rational(hi[k] - a[k]) / d[k];
    if (u > v) std::swap(u, v);
    t0 = std::max(t0, u);
    t1 = std::min(t1, v);
  }
  if (open ? !(t0 < t1 || (s.a == s.b && t0 <= t1)) : t0 > t1) return std::nullopt;
  return std::make_pair(t0, t1);
}

// Area of the ring clipped to the box (Sutherland-Hodgman, one side at a time).
cpp_rational ref_clipped_area(const Ring& ring, const Box64& b) {
  std::vector<QPoint> poly;
  for (Point64 p : ring) poly.push_back(q(p));
  for (int side = 0; side < 4; ++side) {
    auto keep = [&](const QPoint& p) {
      switch (side) {
        case 0:
          return p.x >= b.min.x;
        case 1:
          return p.x <= b.max.x;
        case 2:
          return p.y >= b.min.y;
        default:
          return p.y <= b.max.y;
      }
    };
    auto cut = [&](const QPoint& p, const QPoint& r) {
      const bool vertical = side < 2;
      const cpp_rational c = side == 0   ? b.min.x
                             : side == 1 ? b.max.x
                             : side == 2 ? b.min.y
                                         : b.max.y;
      const cpp_rational t = vertical ? (c - p.x) / (r.x - p.x) : (c - p.y) / (r.y - p.y);
      return QPoint{p.x + t * (r.x - p.x), p.y + t * (r.y - p.y)};
    };
    std::vector<QPoint> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const QPoint& p = poly[i];
      const QPoint& r = poly[(i + 1) % poly.size()];
      if (keep(p)) out.push_back(p);
      if (keep(p) != keep(r)) out.push_back(cut(p, r));
    }
    poly = out;
  }
  cpp_rational area = 0;
  for (std::size_t i = 0; i < poly.size(); ++i)
    area += ref_cross(poly[i], poly[(i + 1) % poly.size()]);
  return area;
}

RC_GTEST_PROP(BoxQueriesProperty, AgreeWithExactClipping, ()) {
  const Grid g = gen_grid();
  const Point64 p = gen_point(g), r = gen_point(g);
  const Box64 box{{std::min(p.x, r.x), std::min(p.y, r.y)},
                  {std::max(p.x, r.x), std::max(p.y, r.y)}};
  const Segment s{gen_point(g), gen_point(g)};
  const auto closed = clip_parameters(s, box);
  const auto want = ref_clip(s, box, false);
  RC_ASSERT(closed.has_value() == want.has_value());
  if (closed) {
    RC_ASSERT(as_rational(closed->t0) == want->first);
    RC_ASSERT(as_rational(closed->t1) == want->second);
  }
  const bool flat = box.min.x == box.max.x || box.min.y == box.max.y;
  RC_LOG() << "box " << box.min.x << ' ' << box.min.y << ' ' << box.max.x << ' ' << box.max.y
           << " segment " << s.a.x << ' ' << s.a.y << ' ' << s.b.x << ' ' << s.b.y << "\n";
  RC_ASSERT(segment_meets_open_box(s, box) == (!flat && ref_clip(s, box, true).has_value()));
  const auto ring = valid_ccw(gen_star_ring(g));
  RC_PRE(ring.has_value());
  RC_ASSERT(interiors_overlap(box, *ring) == (!flat && ref_clipped_area(*ring, box) > 0));
}

}  // namespace
}  // namespace edgeland::test
