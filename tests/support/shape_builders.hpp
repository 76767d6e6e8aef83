#pragma once
// Deterministic builders of integer shapes for the clipper's generators and named tests:
// convex hulls, star polygons, fans, grid-cell sets, combs, and validity-preserving integer
// transforms. Exact integer arithmetic; independent of the library under test except for the
// kernel's validate(), used as the filter that keeps only valid inputs.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/validate.hpp"
#include "polygon_set_helpers.hpp"

namespace edgeland::test {

inline Int128 cross(Point64 o, Point64 a, Point64 b) {
  return Int128(a.x - o.x) * (b.y - o.y) - Int128(a.y - o.y) * (b.x - o.x);
}

// Reverses a clockwise ring so that it is counter-clockwise.
inline Polygon make_ccw(Polygon p) {
  if (twice_area(p) < 0) std::reverse(p.begin(), p.end());
  return p;
}

// Strictly convex hull, counter-clockwise (Andrew's monotone chain). Fewer than 3 vertices
// when the points are collinear.
inline Polygon convex_hull(std::vector<Point64> pts) {
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  Polygon hull(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

// Points sorted counter-clockwise by their exact direction from `center` (half-plane, then
// cross product); of several points in one direction only the first is kept.
inline std::vector<Point64> angular_order(Point64 center, std::vector<Point64> pts) {
  std::erase(pts, center);
  auto upper = [&](Point64 p) { return p.y > center.y || (p.y == center.y && p.x > center.x); };
  auto before = [&](Point64 a, Point64 b) {
    if (upper(a) != upper(b)) return upper(a);
    return cross(center, a, b) > 0;
  };
  std::stable_sort(pts.begin(), pts.end(), before);
  std::vector<Point64> out;
  for (const Point64& p : pts)
    if (out.empty() || before(out.back(), p)) out.push_back(p);
  return out;
}

// The polygon through the points in angular order around `center` (star-shaped when the
// centre is inside). May be invalid; callers filter with validate().
inline Polygon star_polygon(Point64 center, std::vector<Point64> pts) {
  return angular_order(center, std::move(pts));
}

// Triangles (center, p_i, p_i+1) for angularly consecutive points with a left turn: disjoint
// interiors, all sharing the vertex `center` (many edges through one pixel).
inline PolygonSet fan(Point64 center, std::vector<Point64> pts) {
  const std::vector<Point64> ring = angular_order(center, std::move(pts));
  PolygonSet out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % ring.size()];
    if (ring.size() >= 2 && cross(center, a, b) > 0) out.push_back({center, a, b});
  }
  return out;
}

// Unit squares of the given cells (cell size `size`, grid origin `origin`): a set whose members
// share edges and vertices.
inline PolygonSet grid_cells(Point64 origin, std::int64_t size,
                             const std::vector<std::pair<int, int>>& cells) {
  PolygonSet out;
  for (auto [i, j] : cells) {
    const std::int64_t x = origin.x + i * size, y = origin.y + j * size;
    out.push_back({{x, y}, {x + size, y}, {x + size, y + size}, {x, y + size}});
  }
  return out;
}

// An orthogonal comb: a base bar [0, width] x [0, 1] with teeth one unit wide at the even
// x positions in `teeth` (tooth at x spans [x, x+1] x [1, 1 + height]). One-unit wide
// features everywhere (thesis fig. 22).
inline Polygon comb(std::int64_t width,
                    const std::vector<std::pair<std::int64_t, std::int64_t>>& teeth) {
  Polygon p{{0, 0}, {width, 0}, {width, 1}};
  std::vector<std::pair<std::int64_t, std::int64_t>> t = teeth;
  std::sort(t.begin(), t.end(), std::greater<>());
  std::int64_t last = width + 1;
  for (auto [x, h] : t) {
    if (x % 2 != 0 || x + 1 > width - 1 || x + 1 >= last || x < 1 || h < 1) continue;
    p.push_back({x + 1, 1});
    p.push_back({x + 1, 1 + h});
    p.push_back({x, 1 + h});
    p.push_back({x, 1});
    last = x;
  }
  p.push_back({0, 1});
  return p;
}

// An integer affine map x -> M x + t. Maps with det(M) != 0 keep simple polygons simple;
// det < 0 reverses orientation, which apply() undoes.
struct Affine {
  std::int64_t m00 = 1, m01 = 0, m10 = 0, m11 = 1, tx = 0, ty = 0;
  std::int64_t det() const { return m00 * m11 - m01 * m10; }
  std::optional<Point64> operator()(Point64 p) const {
    const Int128 x = Int128(m00) * p.x + Int128(m01) * p.y + tx;
    const Int128 y = Int128(m10) * p.x + Int128(m11) * p.y + ty;
    if (x < -kCoordBound || x > kCoordBound || y < -kCoordBound || y > kCoordBound)
      return std::nullopt;
    return Point64{static_cast<std::int64_t>(x), static_cast<std::int64_t>(y)};
  }
  // The image of the set, or nullopt if a coordinate leaves the range.
  std::optional<PolygonSet> apply(const PolygonSet& set) const {
    PolygonSet out;
    for (const Polygon& poly : set) {
      Polygon q;
      for (const Point64& p : poly) {
        const auto m = (*this)(p);
        if (!m) return std::nullopt;
        q.push_back(*m);
      }
      if (det() < 0) std::reverse(q.begin(), q.end());
      out.push_back(std::move(q));
    }
    return out;
  }
};

inline Affine translation(std::int64_t dx, std::int64_t dy) { return {1, 0, 0, 1, dx, dy}; }

// Members of `candidates` added one at a time, each kept only if the set stays valid.
inline PolygonSet keep_valid(const PolygonSet& candidates) {
  PolygonSet out;
  for (const Polygon& p : candidates) {
    if (!validate(p, 1).ok()) continue;
    out.push_back(p);
    if (!validate(out, 1).ok()) out.pop_back();
  }
  return out;
}

inline std::vector<Point64> all_vertices(const PolygonSet& set) {
  std::vector<Point64> out;
  for (const Polygon& p : set) out.insert(out.end(), p.begin(), p.end());
  return out;
}

}  // namespace edgeland::test
