#include "edgeland/kernel/point_in_polygon.hpp"

#include <algorithm>
#include <cstddef>

#include "edgeland/kernel/predicates.hpp"

namespace edgeland {
namespace {

// One pass of thesis 2.5 over the edges: the signed crossing count of the ray p -> +x, or
// the news that p is on an edge.
struct Scan {
  bool on_boundary = false;
  int winding = 0;
};

Scan scan(Point64 p, const Ring& ring) noexcept {
  Scan s;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 a = ring[i];
    const Point64 b = ring[i + 1 == n ? 0 : i + 1];
    // Rows the edge does not reach can neither hold p nor cross its ray.
    if (std::min(a.y, b.y) > p.y || std::max(a.y, b.y) < p.y) continue;
    const Int128 o = orient_det(a, b, p);
    if (o == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x)) {
      s.on_boundary = true;
      return s;
    }
    // Half-open in y: a vertex on the ray's row counts as below it (thesis 2.5.1).
    if (a.y <= p.y) {
      if (b.y > p.y && o > 0) ++s.winding;  // upward, crossing right of p
    } else {
      if (b.y <= p.y && o < 0) --s.winding;  // downward, crossing right of p
    }
  }
  return s;
}

// The winding number around p + eps (1, eps): the ray from there runs a hair above p's row
// (a vertex on the row is below it: the half-open rule of scan) and starts a hair right of p
// (an edge through p crosses the ray's row left of its start: not counted).
int winding_half_open(Point64 p, const Ring& ring) noexcept {
  int winding = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 a = ring[i];
    const Point64 b = ring[i + 1 == n ? 0 : i + 1];
    if (a.y <= p.y) {
      if (b.y > p.y && orient_det(a, b, p) > 0) ++winding;
    } else if (b.y <= p.y && orient_det(a, b, p) < 0) {
      --winding;
    }
  }
  return winding;
}

// Binary search over [lo, hi] for the last index where `pred` holds; pred(lo) must hold and
// pred must be true then false along the range.
template <class Pred>
std::size_t last_true(std::size_t lo, std::size_t hi, Pred pred) noexcept {
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo + 1) / 2;
    if (pred(mid))
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}

// Same, for the first index where `pred` holds; pred(hi) must hold, false then true.
template <class Pred>
std::size_t first_true(std::size_t lo, std::size_t hi, Pred pred) noexcept {
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (pred(mid))
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

// p lies on the line through v_0 and one of its neighbours. That line supports the convex
// ring, so p is in the region exactly when it is on the boundary, which meets the line in
// the chain of collinear vertices running from v_0 towards v_1 and towards v_(n-1).
PointLocation on_supporting_line(Point64 p, const Ring& r) noexcept {
  const std::size_t n = r.size();
  const Point64 v0 = r[0], first = r[1], last = r[n - 1];
  // Vertices ahead of v_0 on the line v_0 v_1 are v_1 .. v_m (contiguous by convexity).
  const std::size_t m1 = last_true(1, n - 1, [&](std::size_t k) {
    return orientation(v0, first, r[k]) == Orientation::kCollinear && dot_sign(v0, first, r[k]) > 0;
  });
  // Vertices ahead of v_0 on the line v_0 v_(n-1) are v_m .. v_(n-1).
  const std::size_t m2 = first_true(1, n - 1, [&](std::size_t k) {
    return orientation(v0, last, r[k]) == Orientation::kCollinear && dot_sign(v0, last, r[k]) > 0;
  });
  if (on_segment(p, {v0, r[m1]}) || on_segment(p, {v0, r[m2]})) return PointLocation::kOnBoundary;
  return PointLocation::kOutside;
}

}  // namespace

int winding_number(Point64 p, const Ring& ring) noexcept { return scan(p, ring).winding; }

PointLocation locate(Point64 p, const Ring& ring) noexcept {
  const Scan s = scan(p, ring);
  if (s.on_boundary) return PointLocation::kOnBoundary;
  return s.winding != 0 ? PointLocation::kInside : PointLocation::kOutside;
}

PointLocation locate_convex(Point64 p, const Ring& r) noexcept {
  const std::size_t n = r.size();
  if (n < 3) return locate(p, r);
  const Point64 v0 = r[0];
  if (p == v0) return PointLocation::kOnBoundary;
  // Outside the wedge that the ring spans at v_0 (an angle of at most 180 degrees).
  const Orientation o_first = orientation(v0, r[1], p);
  const Orientation o_last = orientation(v0, r[n - 1], p);
  if (o_first == Orientation::kClockwise || o_last == Orientation::kCounterClockwise) {
    return PointLocation::kOutside;
  }
  if (o_first == Orientation::kCollinear || o_last == Orientation::kCollinear) {
    return on_supporting_line(p, r);
  }
  // p is strictly inside the wedge. The fan directions v_k - v_0 turn counter-clockwise
  // over at most 180 degrees, so "p strictly left of v_0 -> v_k" is true then false in k.
  const std::size_t k = last_true(1, n - 2, [&](std::size_t j) {
    return orientation(v0, r[j], p) == Orientation::kCounterClockwise;
  });
  // p is in the wedge of the (non-degenerate) fan triangle v_0 v_k v_(k+1), excluding its
  // side v_0 v_k; the side v_0 v_(k+1) is a chord inside the ring, never its boundary.
  switch (orientation(r[k], r[k + 1], p)) {
    case Orientation::kCounterClockwise:
      return PointLocation::kInside;
    case Orientation::kCollinear:
      return PointLocation::kOnBoundary;
    case Orientation::kClockwise:
      return PointLocation::kOutside;
  }
  return PointLocation::kOutside;  // Not reached by tests: the switch covers every Orientation.
}

PointLocation locate(Point64 p, const PolygonSet& set, const std::vector<Box64>& boxes) noexcept {
  for (std::size_t i = 0; i < set.size(); ++i) {
    if (set[i].empty() || !boxes[i].contains(p)) continue;
    const PointLocation where = locate(p, set[i]);
    // Interiors are disjoint and each member has area near its boundary, so the first
    // member that does not report kOutside decides.
    if (where != PointLocation::kOutside) return where;
  }
  return PointLocation::kOutside;
}

PointLocation locate(Point64 p, const PolygonSet& set) noexcept {
  for (const Polygon& member : set) {
    const std::optional<Box64> box = bounding_box(member);
    if (!box || !box->contains(p)) continue;
    const PointLocation where = locate(p, member);
    if (where != PointLocation::kOutside) return where;
  }
  return PointLocation::kOutside;
}

bool inside_half_open(Point64 p, const Ring& ring) noexcept {
  return winding_half_open(p, ring) != 0;
}

}  // namespace edgeland
