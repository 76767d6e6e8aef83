#include "edgeland/kernel/predicates.hpp"

#include <algorithm>
#include <utility>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"

namespace edgeland {
namespace {

using W = arith::Checked<Int128>;

constexpr int sign(Int128 v) noexcept { return (v > 0) - (v < 0); }

// Position of p along the segment direction a->b, used to order collinear points.
Int128 along(Point64 a, Point64 b, Point64 p) noexcept {
  return formulas::dot_widening<arith::Checked<std::int64_t>, W>(a.x, a.y, b.x, b.y, p.x, p.y).v;
}

}  // namespace

int dot_sign(Point64 a, Point64 b, Point64 c) noexcept { return sign(along(a, b, c)); }

bool on_segment(Point64 p, const Segment& s) noexcept {
  if (orient_det(s.a, s.b, p) != 0) return false;
  return segment_box(s).contains(p);
}

bool on_segment_interior(Point64 p, const Segment& s) noexcept {
  return p != s.a && p != s.b && on_segment(p, s);
}

std::optional<RationalPoint> line_intersection(const Segment& s, const Segment& t) noexcept {
  const auto h =
      formulas::line_intersection<W>(s.a.x, s.a.y, s.b.x, s.b.y, t.a.x, t.a.y, t.b.x, t.b.y);
  if (h.den.v == 0) return std::nullopt;
  // Negating cannot overflow: the proofs bound every component well inside (-2^127, 2^127).
  if (h.den.v < 0) return RationalPoint{-h.x_num.v, -h.y_num.v, -h.den.v};
  return RationalPoint{h.x_num.v, h.y_num.v, h.den.v};
}

namespace {

RationalPoint integer_point(Point64 p) noexcept { return RationalPoint{p.x, p.y, 1}; }

// Both segments lie on one line: compare their extents along it.
SegmentIntersection collinear_intersection(const Segment& s, const Segment& t) noexcept {
  Point64 s0 = std::min(s.a, s.b), s1 = std::max(s.a, s.b);
  Point64 t0 = std::min(t.a, t.b), t1 = std::max(t.a, t.b);
  // On a common line the lexicographic order of points is the order along the line.
  const Point64 lo = std::max(s0, t0), hi = std::min(s1, t1);
  SegmentIntersection r;
  if (hi < lo) return r;
  if (lo == hi) {
    r.relation = SegmentRelation::kTouching;
    r.point = integer_point(lo);
    return r;
  }
  r.relation = SegmentRelation::kOverlapping;
  r.overlap_from = lo;
  r.overlap_to = hi;
  return r;
}

SegmentIntersection point_against_segment(Point64 p, const Segment& t) noexcept {
  SegmentIntersection r;
  if (on_segment(p, t)) {
    r.relation = SegmentRelation::kTouching;
    r.point = integer_point(p);
  }
  return r;
}

}  // namespace

SegmentIntersection intersect(const Segment& s, const Segment& t) noexcept {
  if (s.a == s.b) return point_against_segment(s.a, t);
  if (t.a == t.b) return point_against_segment(t.a, s);
  SegmentIntersection r;
  // Most pairs a clipper asks about are disjoint: reject on the first side test that allows it.
  const int o1 = sign(orient_det(s.a, s.b, t.a));
  const int o2 = sign(orient_det(s.a, s.b, t.b));
  if (o1 * o2 > 0) return r;  // t strictly on one side of the line of s
  if (o1 == 0 && o2 == 0) return collinear_intersection(s, t);
  const int o3 = sign(orient_det(t.a, t.b, s.a));
  const int o4 = sign(orient_det(t.a, t.b, s.b));
  if (o3 * o4 > 0) return r;
  // From here the lines cross at exactly one point, which lies on both closed segments.
  if (o1 == 0 || o2 == 0 || o3 == 0 || o4 == 0) {
    r.relation = SegmentRelation::kTouching;
    const Point64 p = o1 == 0 ? t.a : o2 == 0 ? t.b : o3 == 0 ? s.a : s.b;
    r.point = integer_point(p);
    return r;
  }
  r.relation = SegmentRelation::kCrossing;
  r.point = *line_intersection(s, t);
  return r;
}

Int128 squared_distance(Point64 a, Point64 b) noexcept {
  return formulas::dot_widening<arith::Checked<std::int64_t>, W>(a.x, a.y, b.x, b.y, b.x, b.y).v;
}

bool is_exactly(const RationalPoint& r, Point64 p) noexcept {
  return formulas::scaled<W>(p.x, r.den) == W(r.x_num) &&
         formulas::scaled<W>(p.y, r.den) == W(r.y_num);
}

Point64 round_to_grid(const RationalPoint& p) noexcept {
  const W x = formulas::round_half_up<W>(p.x_num, p.den);
  const W y = formulas::round_half_up<W>(p.y_num, p.den);
  return Point64{static_cast<std::int64_t>(x.v), static_cast<std::int64_t>(y.v)};
}

}  // namespace edgeland
