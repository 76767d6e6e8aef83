#pragma once
// Independent exact references for the kernel tests, computed in Boost.Multiprecision
// (cpp_int / cpp_rational) straight from the definitions, sharing no code with the kernel.
#include <algorithm>
#include <boost/multiprecision/cpp_int.hpp>
#include <cstddef>
#include <optional>
#include <vector>

#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "support/big_int.hpp"

namespace edgeland::test {

using boost::multiprecision::cpp_int;
using boost::multiprecision::cpp_rational;

inline int sgn(const cpp_int& v) { return v.sign(); }
inline int sgn(const cpp_rational& v) { return v.sign(); }

struct QPoint {
  cpp_rational x, y;
  friend bool operator==(const QPoint&, const QPoint&) = default;
};

inline QPoint q(Point64 p) { return {cpp_rational(p.x), cpp_rational(p.y)}; }
inline QPoint q(const RationalPoint& p) {
  return {cpp_rational(big(p.x_num), big(p.den)), cpp_rational(big(p.y_num), big(p.den))};
}

inline cpp_int ref_cross(const cpp_int& ax, const cpp_int& ay, const cpp_int& bx,
                         const cpp_int& by) {
  return ax * by - ay * bx;
}
inline cpp_int ref_orient_det(Point64 a, Point64 b, Point64 c) {
  return ref_cross(cpp_int(b.x) - a.x, cpp_int(b.y) - a.y, cpp_int(c.x) - a.x, cpp_int(c.y) - a.y);
}
inline cpp_rational ref_cross(const QPoint& a, const QPoint& b) { return a.x * b.y - a.y * b.x; }
inline QPoint operator-(const QPoint& a, const QPoint& b) { return {a.x - b.x, a.y - b.y}; }
inline cpp_rational dot(const QPoint& a, const QPoint& b) { return a.x * b.x + a.y * b.y; }

// p on the closed segment ab (a point if a == b), from the definition: p = a + s (b - a)
// for some s in [0, 1].
inline bool ref_on_segment(const QPoint& p, const QPoint& a, const QPoint& b) {
  const QPoint d = b - a, w = p - a;
  if (d.x == 0 && d.y == 0) return p == a;
  if (ref_cross(d, w) != 0) return false;
  const cpp_rational s = dot(w, d) / dot(d, d);
  return s >= 0 && s <= 1;
}

// The intersection of a query (closed segment, or the infinite line through it) with the
// closed segment [e0, e1]: nothing, one point, or a segment of positive length.
struct RefMeet {
  enum Kind { kNone, kPoint, kInterval } kind = kNone;
  QPoint a, b;  // kPoint: a. kInterval: a and b, in the order of the segment e0 -> e1.
};

inline RefMeet ref_meet(const QPoint& p0, const QPoint& p1, bool infinite_line, const QPoint& e0,
                        const QPoint& e1) {
  RefMeet m;
  const QPoint r = p1 - p0, s = e1 - e0;
  const bool query_point = r.x == 0 && r.y == 0;
  if (query_point) {
    if (ref_on_segment(p0, e0, e1)) {
      m.kind = RefMeet::kPoint;
      m.a = p0;
    }
    return m;
  }
  auto in_query = [&](const cpp_rational& t) { return infinite_line || (t >= 0 && t <= 1); };
  const cpp_rational den = ref_cross(r, s);
  if (den != 0) {
    // p0 + t r = e0 + u s.
    const cpp_rational t = ref_cross(e0 - p0, s) / den;
    const cpp_rational u = ref_cross(e0 - p0, r) / den;
    if (in_query(t) && u >= 0 && u <= 1) {
      m.kind = RefMeet::kPoint;
      m.a = {p0.x + t * r.x, p0.y + t * r.y};
    }
    return m;
  }
  if (ref_cross(e0 - p0, r) != 0) return m;  // parallel, apart
  // Collinear: intersect the parameter ranges along the query's direction.
  const cpp_rational rr = dot(r, r);
  const cpp_rational t0 = dot(e0 - p0, r) / rr, t1 = dot(e1 - p0, r) / rr;
  cpp_rational lo = t0 < t1 ? t0 : t1, hi = t0 < t1 ? t1 : t0;
  if (!infinite_line) {
    if (lo < 0) lo = 0;
    if (hi > 1) hi = 1;
  }
  if (lo > hi) return m;
  const QPoint a{p0.x + lo * r.x, p0.y + lo * r.y}, b{p0.x + hi * r.x, p0.y + hi * r.y};
  if (lo == hi) {
    m.kind = RefMeet::kPoint;
    m.a = a;
    return m;
  }
  m.kind = RefMeet::kInterval;
  // Order along the edge.
  const bool forward = dot(b - a, s) > 0;
  m.a = forward ? a : b;
  m.b = forward ? b : a;
  return m;
}

// Twice the signed area by the shoelace formula.
inline cpp_int ref_twice_area(const Ring& ring) {
  cpp_int sum = 0;
  const std::size_t n = ring.size();
  if (n < 3) return 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % n];
    sum += cpp_int(a.x) * b.y - cpp_int(a.y) * b.x;
  }
  return sum;
}

inline bool ref_on_boundary(Point64 p, const Ring& ring) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (ref_on_segment(q(p), q(ring[i]), q(ring[(i + 1) % ring.size()]))) return true;
  }
  return false;
}

// Winding number by summing the signed angle each edge sweeps around p, counted in
// quarter turns: the quadrant of each vertex around p, and for a jump of two quadrants
// (the edge passes on one side of p or the other) the sign of the cross product decides.
// p must not be on the boundary.
inline int ref_winding(Point64 p, const Ring& ring) {
  auto quadrant = [&](Point64 v) {
    const cpp_int x = cpp_int(v.x) - p.x, y = cpp_int(v.y) - p.y;
    if (x > 0 && y >= 0) return 0;
    if (x <= 0 && y > 0) return 1;
    if (x < 0 && y <= 0) return 2;
    return 3;  // x >= 0 && y < 0 (v == p excluded by the precondition)
  };
  int quarters = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % n];
    int delta = (quadrant(b) - quadrant(a) + 4) % 4;
    if (delta == 3) delta = -1;
    if (delta == 2) delta = sgn(ref_orient_det(p, a, b)) > 0 ? 2 : -2;
    quarters += delta;
  }
  return quarters / 4;
}

// Convex hull (Andrew's monotone chain) of the points, strictly convex, counter-clockwise.
inline std::vector<Point64> ref_convex_hull(std::vector<Point64> pts) {
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  std::vector<Point64> h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && sgn(ref_orient_det(h[k - 2], h[k - 1], pts[i])) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && sgn(ref_orient_det(h[k - 2], h[k - 1], pts[i - 1])) <= 0) --k;
    h[k++] = pts[i - 1];
  }
  h.resize(k - 1);
  return h;
}

}  // namespace edgeland::test
