#include "segment_reference.hpp"

#include <algorithm>

namespace edgeland::exhaustive {
namespace {

using boost::multiprecision::cpp_int;

RationalXY at(const Segment& s, const Rational& lambda) {  // s.a + lambda (s.b - s.a)
  return {Rational(s.a.x) + lambda * (s.b.x - s.a.x), Rational(s.a.y) + lambda * (s.b.y - s.a.y)};
}

bool lex_less(const RationalXY& a, const RationalXY& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// n / d. Boost 1.74's rational<cpp_int> throws on a negative denominator (it compares it with
// -numeric_limits<cpp_int>::max(), which is 0 for an unbounded type), so normalize here.
Rational ratio(const cpp_int& n, const cpp_int& d) {
  return d < 0 ? Rational(-n, -d) : Rational(n, d);
}

cpp_int cross(cpp_int ax, cpp_int ay, cpp_int bx, cpp_int by) { return ax * by - ay * bx; }

// The parameter of the point p on the line through a non-degenerate s, given that p is on it.
Rational parameter_of(Point64 p, const Segment& s) {
  const cpp_int dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  return dx != 0 ? ratio(p.x - s.a.x, dx) : ratio(p.y - s.a.y, dy);
}

}  // namespace

bool reference_on_segment(Point64 p, const Segment& s) {
  if (s.a == s.b) return p == s.a;
  const Rational lambda = parameter_of(p, s);
  return lambda >= 0 && lambda <= 1 && at(s, lambda) == RationalXY{p.x, p.y};
}

ReferenceIntersection reference_intersect(const Segment& s, const Segment& t) {
  ReferenceIntersection r;
  auto touch = [&r](Point64 p) {
    r.relation = SegmentRelation::kTouching;
    r.point = {p.x, p.y};
    return r;
  };
  if (s.a == s.b) return reference_on_segment(s.a, t) ? touch(s.a) : r;
  if (t.a == t.b) return reference_on_segment(t.a, s) ? touch(t.a) : r;

  // s.a + lambda (s.b - s.a) = t.a + mu (t.b - t.a), solved by Cramer's rule.
  const cpp_int rx = s.b.x - s.a.x, ry = s.b.y - s.a.y, qx = t.b.x - t.a.x, qy = t.b.y - t.a.y;
  const cpp_int wx = t.a.x - s.a.x, wy = t.a.y - s.a.y;
  cpp_int det = cross(rx, ry, qx, qy);
  if (det != 0) {
    // lambda = ln / det, mu = mn / det; with det > 0, lambda in [0, 1] iff 0 <= ln <= det.
    cpp_int ln = cross(wx, wy, qx, qy), mn = cross(wx, wy, rx, ry);
    if (det < 0) {
      det = -det;
      ln = -ln;
      mn = -mn;
    }
    if (ln < 0 || ln > det || mn < 0 || mn > det) return r;
    const Rational lambda(ln, det);
    const bool interior = ln > 0 && ln < det && mn > 0 && mn < det;
    r.relation = interior ? SegmentRelation::kCrossing : SegmentRelation::kTouching;
    r.point = at(s, lambda);
    return r;
  }
  if (cross(rx, ry, wx, wy) != 0) return r;  // parallel, on different lines
  // One line: intersect the parameter intervals [0, 1] of s and [l0, l1] of t along s.
  const Rational l0 = parameter_of(t.a, s), l1 = parameter_of(t.b, s);
  const Rational lo = std::max(Rational(0), std::min(l0, l1));
  const Rational hi = std::min(Rational(1), std::max(l0, l1));
  if (lo > hi) return r;
  if (lo == hi) {
    r.relation = SegmentRelation::kTouching;
    r.point = at(s, lo);
    return r;
  }
  r.relation = SegmentRelation::kOverlapping;
  r.from = at(s, lo);
  r.to = at(s, hi);
  if (lex_less(r.to, r.from)) std::swap(r.from, r.to);
  return r;
}

}  // namespace edgeland::exhaustive
