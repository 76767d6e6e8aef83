// Properties of predicates.hpp against exact Boost.Multiprecision references, on inputs from
// tiny grids (degenerate cases) up to the full coordinate range.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "edgeland/kernel/predicates.hpp"
#include "exact_reference.hpp"
#include "random_geometry.hpp"
#include "support/big_int.hpp"

namespace edgeland::test {
namespace {

int sign_of(Orientation o) { return static_cast<int>(o); }

Segment gen_segment(const Grid& g) { return {gen_point(g), gen_point(g)}; }

RC_GTEST_PROP(OrientationProperty, MatchesExactDeterminant, ()) {
  const Grid g = gen_grid();
  const Point64 a = gen_point(g), b = gen_point(g), c = gen_point(g);
  const cpp_int ref = ref_orient_det(a, b, c);
  RC_ASSERT(big(orient_det(a, b, c)) == ref);
  RC_ASSERT(sign_of(orientation(a, b, c)) == sgn(ref));
}

RC_GTEST_PROP(OrientationProperty, AntisymmetricInItsFirstTwoPoints, ()) {
  const Grid g = gen_grid();
  const Point64 a = gen_point(g), b = gen_point(g), c = gen_point(g);
  RC_ASSERT(sign_of(orientation(a, b, c)) == -sign_of(orientation(b, a, c)));
  RC_ASSERT(sign_of(orientation(a, b, c)) == -sign_of(orientation(a, c, b)));
}

RC_GTEST_PROP(OrientationProperty, InvariantUnderCyclicShift, ()) {
  const Grid g = gen_grid();
  const Point64 a = gen_point(g), b = gen_point(g), c = gen_point(g);
  RC_ASSERT(orientation(a, b, c) == orientation(b, c, a));
  RC_ASSERT(orientation(a, b, c) == orientation(c, a, b));
  RC_ASSERT(orient_det(a, b, c) == orient_det(b, c, a));
}

RC_GTEST_PROP(DotSignProperty, MatchesExactDotProduct, ()) {
  const Grid g = gen_grid();
  const Point64 a = gen_point(g), b = gen_point(g), c = gen_point(g);
  const cpp_int ref =
      (cpp_int(b.x) - a.x) * (cpp_int(c.x) - a.x) + (cpp_int(b.y) - a.y) * (cpp_int(c.y) - a.y);
  RC_ASSERT(dot_sign(a, b, c) == sgn(ref));
}

RC_GTEST_PROP(OnSegmentProperty, MatchesRationalReference, ()) {
  const Grid g = gen_grid();
  const Segment s = gen_segment(g);
  // Often pick p among the segment's own endpoints or on its line, else anywhere.
  const Point64 p = *rc::gen::inRange(0, 3) == 0 ? *rc::gen::element(s.a, s.b) : gen_point(g);
  const bool ref = ref_on_segment(q(p), q(s.a), q(s.b));
  RC_ASSERT(on_segment(p, s) == ref);
  RC_ASSERT(on_segment_interior(p, s) == (ref && p != s.a && p != s.b));
}

RC_GTEST_PROP(IntersectProperty, ClassificationMatchesRationalReference, ()) {
  const Grid g = gen_grid();
  const Segment s = gen_segment(g);
  const Segment t = *rc::gen::inRange(0, 4) == 0 ? Segment{s.b, gen_point(g)} : gen_segment(g);
  const SegmentIntersection r = intersect(s, t);
  const RefMeet m = ref_meet(q(s.a), q(s.b), false, q(t.a), q(t.b));
  switch (m.kind) {
    case RefMeet::kNone:
      RC_ASSERT(r.relation == SegmentRelation::kDisjoint);
      break;
    case RefMeet::kPoint: {
      const bool at_endpoint = m.a == q(s.a) || m.a == q(s.b) || m.a == q(t.a) || m.a == q(t.b);
      RC_ASSERT(r.relation ==
                (at_endpoint ? SegmentRelation::kTouching : SegmentRelation::kCrossing));
      RC_ASSERT(r.point.den > 0);
      RC_ASSERT(q(r.point) == m.a);
      break;
    }
    case RefMeet::kInterval:
      RC_ASSERT(r.relation == SegmentRelation::kOverlapping);
      RC_ASSERT(r.overlap_from < r.overlap_to);  // lexicographic order, as documented
      RC_ASSERT((q(r.overlap_from) == m.a && q(r.overlap_to) == m.b) ||
                (q(r.overlap_from) == m.b && q(r.overlap_to) == m.a));
      break;
  }
}

RC_GTEST_PROP(IntersectProperty, SymmetricInItsArguments, ()) {
  const Grid g = gen_grid();
  const Segment s = gen_segment(g), t = gen_segment(g);
  const SegmentIntersection st = intersect(s, t), ts = intersect(t, s);
  RC_ASSERT(st.relation == ts.relation);
  if (st.relation == SegmentRelation::kCrossing || st.relation == SegmentRelation::kTouching) {
    RC_ASSERT(q(st.point) == q(ts.point));
  }
  if (st.relation == SegmentRelation::kOverlapping) {
    RC_ASSERT(st.overlap_from == ts.overlap_from);
    RC_ASSERT(st.overlap_to == ts.overlap_to);
  }
}

RC_GTEST_PROP(LineIntersectionProperty, MatchesRationalReference, ()) {
  const Grid g = gen_grid();
  const Segment s = gen_segment(g), t = gen_segment(g);
  const auto r = line_intersection(s, t);
  const QPoint ds = q(s.b) - q(s.a), dt = q(t.b) - q(t.a);
  const cpp_rational den = ref_cross(ds, dt);
  if (den == 0) {
    RC_ASSERT(!r.has_value());
    return;
  }
  RC_ASSERT(r.has_value());
  RC_ASSERT(r->den > 0);
  const cpp_rational u = ref_cross(q(t.a) - q(s.a), dt) / den;
  const QPoint expected{q(s.a).x + u * ds.x, q(s.a).y + u * ds.y};
  RC_ASSERT(q(*r) == expected);
}

// is_exactly(r, p) says whether the rational point r is the integer point p; checked against
// exact rationals at the rounded crossing (often exact on small grids) and at a neighbour.
RC_GTEST_PROP(IsExactlyProperty, MatchesRationalEquality, ()) {
  const Grid g = gen_grid();
  const auto r = line_intersection(gen_segment(g), gen_segment(g));
  RC_PRE(r.has_value());
  const QPoint v = q(*r);
  RC_PRE(abs(v.x) <= B && abs(v.y) <= B);  // is_exactly takes in-range integer points
  const Point64 p = round_to_grid(*r);
  RC_ASSERT(is_exactly(*r, p) == (v == q(p)));
  RC_ASSERT(is_exactly(*r, p) == r->is_integer());
  const Point64 next{p.x + (p.x < B ? 1 : -1), p.y};
  RC_ASSERT(!is_exactly(*r, next));
}

TEST(IsExactly, TakesEveryDenominator) {
  // Same point over different denominators, negative coordinates, and a near miss.
  EXPECT_TRUE(is_exactly({-6, 9, 3}, {-2, 3}));
  const Int128 big = Int128(1) << 66;  // above any crossing's denominator
  EXPECT_TRUE(is_exactly({-Int128(B) * big, Int128(B) * big, big}, {-B, B}));
  EXPECT_FALSE(is_exactly({-Int128(B) * big + 1, Int128(B) * big, big}, {-B, B}));
  EXPECT_FALSE(is_exactly({-6, 10, 3}, {-2, 3}));
  EXPECT_FALSE(is_exactly({7, 0, 2}, {3, 0}));
}

RC_GTEST_PROP(SquaredDistanceProperty, MatchesExactSum, ()) {
  const Grid g = gen_grid();
  const Point64 a = gen_point(g), b = gen_point(g);
  const cpp_int dx = cpp_int(b.x) - a.x, dy = cpp_int(b.y) - a.y;
  RC_ASSERT(big(squared_distance(a, b)) == dx * dx + dy * dy);
  RC_ASSERT(squared_distance(a, b) == squared_distance(b, a));
}

// r is the nearest integer to v, halves going up: r - 1/2 <= v < r + 1/2.
bool nearest_halves_up(std::int64_t r, const cpp_rational& v) {
  const cpp_rational half(1, 2);
  return cpp_rational(r) - half <= v && v < cpp_rational(r) + half;
}

RC_GTEST_PROP(RoundToGridProperty, NearestIntegerHalvesUpForIntersections, ()) {
  const Grid g = gen_grid();
  const auto r = line_intersection(gen_segment(g), gen_segment(g));
  RC_PRE(r.has_value());
  // Only intersections of segments have an in-range rounding (predicates.hpp).
  const QPoint v = q(*r);
  RC_PRE(abs(v.x) <= B && abs(v.y) <= B);
  const Point64 p = round_to_grid(*r);
  RC_ASSERT(nearest_halves_up(p.x, v.x));
  RC_ASSERT(nearest_halves_up(p.y, v.y));
}

RC_GTEST_PROP(RoundToGridProperty, NearestIntegerHalvesUpForAnyInRangeFraction, ()) {
  // value = whole + rem / den with |whole| <= B, 0 <= rem < den; small denominators make
  // exact halves common.
  const Int128 den = *rc::gen::element(0, 1) == 0
                         ? Int128(*rc::gen::inRange<std::int64_t>(1, 7))
                         : Int128(*rc::gen::inRange<std::int64_t>(1, std::int64_t(1) << 62));
  auto component = [&] {
    const Int128 whole = *rc::gen::inRange<std::int64_t>(-B, B);
    const Int128 rem =
        static_cast<Int128>(static_cast<unsigned __int128>(*rc::gen::arbitrary<std::uint64_t>()) %
                            static_cast<unsigned __int128>(den));
    return whole * den + rem;
  };
  const RationalPoint v{component(), component(), den};
  const Point64 p = round_to_grid(v);
  RC_ASSERT(nearest_halves_up(p.x, q(v).x));
  RC_ASSERT(nearest_halves_up(p.y, q(v).y));
}

}  // namespace
}  // namespace edgeland::test
