#pragma once
// RapidCheck generators for kernel properties. Every test case first picks a Grid, then all
// of its coordinates from that grid, so that tiny grids produce the degenerate cases
// (collinear triples, shared vertices, overlaps) and the full grid the extreme magnitudes.
#include <rapidcheck.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <ostream>
#include <vector>

#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "exact_reference.hpp"

namespace edgeland {

// Readable counterexamples.
inline void showValue(const Point64& p, std::ostream& os) { os << '(' << p.x << ' ' << p.y << ')'; }

namespace test {

inline constexpr std::int64_t B = kCoordBound;

// A set of coordinates for one test case: [lo_x, lo_x + width] x [lo_y, lo_y + width].
struct Grid {
  std::int64_t lo_x = 0, lo_y = 0, width = 0;
  bool extremes_only = false;  // only the values -B, -B+1, -1, 0, 1, B-1, B
};

// Tiny grids centred at 0 or pushed against the bound (degeneracies at the largest
// magnitudes), a small grid, the full range, and the extreme values.
inline Grid gen_grid() {
  const int kind = *rc::gen::inRange(0, 6);
  Grid g;
  switch (kind) {
    case 0:
      g = {-3, -3, 6};
      break;
    case 1: {
      const std::int64_t ox = *rc::gen::element<std::int64_t>(-B, B - 6, -3);
      const std::int64_t oy = *rc::gen::element<std::int64_t>(-B, B - 6, -3);
      g = {ox, oy, 6};
      break;
    }
    case 2:
      g = {-40, -40, 80};
      break;
    case 3:
    case 4:
      g = {-B, -B, 2 * B};
      break;
    default:
      g.extremes_only = true;
      break;
  }
  return g;
}

inline std::int64_t gen_coord(std::int64_t lo, std::int64_t width, bool extremes_only) {
  if (extremes_only) return *rc::gen::element<std::int64_t>(-B, -B + 1, -1, 0, 1, B - 1, B);
  return lo + *rc::gen::inRange<std::int64_t>(0, width + 1);
}

inline Point64 gen_point(const Grid& g) {
  return {gen_coord(g.lo_x, g.width, g.extremes_only), gen_coord(g.lo_y, g.width, g.extremes_only)};
}

inline std::vector<Point64> gen_points(const Grid& g, std::size_t min_n, std::size_t max_n) {
  const auto n = *rc::gen::inRange(min_n, max_n + 1);
  std::vector<Point64> pts;
  for (std::size_t i = 0; i < n; ++i) pts.push_back(gen_point(g));
  return pts;
}

// Any ring: self-intersections, repeated vertices, spikes and either orientation happen.
inline Ring gen_ring(const Grid& g, std::size_t max_n = 9) { return gen_points(g, 3, max_n); }

inline Ring rotated(const Ring& r, std::size_t k) {
  Ring out;
  for (std::size_t i = 0; i < r.size(); ++i) out.push_back(r[(i + k) % r.size()]);
  return out;
}

// A convex counter-clockwise ring: the hull of random points, with lattice points inserted
// on some edges (collinear vertices) and a random start vertex. Discards hulls of < 3.
inline Ring gen_convex_ring(const Grid& g) {
  const Ring hull = ref_convex_hull(gen_points(g, 3, 12));
  RC_PRE(hull.size() >= 3);
  Ring ring;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Point64 a = hull[i], b = hull[(i + 1) % hull.size()];
    ring.push_back(a);
    const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
    const std::int64_t steps = std::gcd(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy);
    if (steps > 1 && *rc::gen::inRange(0, 3) == 0) {
      // One lattice point strictly inside the edge.
      const std::int64_t j =
          1 + *rc::gen::inRange<std::int64_t>(0, std::min<std::int64_t>(steps - 1, 1000));
      ring.push_back({a.x + dx / steps * j, a.y + dy / steps * j});
    }
  }
  return rotated(ring, *rc::gen::inRange<std::size_t>(0, ring.size()));
}

// A simple counter-clockwise ring, star-shaped around a centre c: one point strictly inside
// each quadrant around c (so every angular gap is below 180 degrees) plus random points,
// sorted by angle around c, one per direction. Never discards.
inline Ring gen_star_ring(Grid g) {
  if (g.extremes_only) g = {-B, -B, 2 * B};
  auto coord_between = [](std::int64_t lo, std::int64_t hi) {
    return lo + *rc::gen::inRange<std::int64_t>(0, hi - lo + 1);
  };
  const Point64 c{coord_between(g.lo_x + 1, g.lo_x + g.width - 1),
                  coord_between(g.lo_y + 1, g.lo_y + g.width - 1)};
  auto side = [&](std::int64_t lo, std::int64_t centre, int s) {
    return s > 0 ? coord_between(centre + 1, lo + g.width) : coord_between(lo, centre - 1);
  };
  std::vector<Point64> pts;
  for (const int sx : {1, -1}) {
    for (const int sy : {1, -1}) pts.push_back({side(g.lo_x, c.x, sx), side(g.lo_y, c.y, sy)});
  }
  for (const Point64 p : gen_points(g, 0, 6)) {
    if (p != c) pts.push_back(p);
  }
  auto half = [&](Point64 p) {
    const std::int64_t x = p.x - c.x, y = p.y - c.y;
    return (y > 0 || (y == 0 && x > 0)) ? 0 : 1;
  };
  auto cross = [&](Point64 a, Point64 b) {
    return sgn(
        ref_cross(cpp_int(a.x) - c.x, cpp_int(a.y) - c.y, cpp_int(b.x) - c.x, cpp_int(b.y) - c.y));
  };
  auto same_direction = [&](Point64 a, Point64 b) {
    return half(a) == half(b) && cross(a, b) == 0;
  };
  std::sort(pts.begin(), pts.end(), [&](Point64 a, Point64 b) {
    if (half(a) != half(b)) return half(a) < half(b);
    const int s = cross(a, b);
    if (s != 0) return s > 0;
    return a < b;
  });
  Ring ring;
  for (const Point64 p : pts) {
    if (ring.empty() || !same_direction(ring.back(), p)) ring.push_back(p);
  }
  return rotated(ring, *rc::gen::inRange<std::size_t>(0, ring.size()));
}

}  // namespace test
}  // namespace edgeland
