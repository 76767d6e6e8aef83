#pragma once
// Generators of valid polygons and polygon sets for the validate() tests, written over a
// `draw(lo, hi)` callable returning an integer in [lo, hi): RapidCheck draws in properties,
// a fixed-seed SplitMixDraw in the large deterministic tests.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/splitmix64.hpp"

namespace edgeland::testing {

// Deterministic integers for large inputs: the project's one seeded generator (kernel/:
// splitmix64.hpp) as a `draw(lo, hi)` in [lo, hi), the same sequence on every platform.
class SplitMixDraw : public SplitMix64 {
 public:
  using SplitMix64::SplitMix64;
  std::int64_t operator()(std::int64_t lo, std::int64_t hi) {
    return lo + static_cast<std::int64_t>(below(static_cast<std::uint64_t>(hi - lo)));
  }
};

// The star-shaped ring center + d over the directions d sorted counter-clockwise by angle,
// one per direction (the first of parallel ones is kept). Strictly simple and CCW when
// consecutive directions turn by less than a half turn; returns an empty ring otherwise.
Ring star_from_directions(Point64 center, std::vector<Point64> directions);

// A random star-shaped ring of about `count` vertices within `radius` of `center`. The four
// axis directions are always present, so no gap between directions reaches a half turn.
template <class Draw>
Ring random_star(Draw& draw, Point64 center, std::int64_t radius, std::size_t count) {
  std::vector<Point64> d{{draw(1, radius + 1), 0},
                         {0, draw(1, radius + 1)},
                         {-draw(1, radius + 1), 0},
                         {0, -draw(1, radius + 1)}};
  while (d.size() < count) {
    const Point64 p{draw(-radius, radius + 1), draw(-radius, radius + 1)};
    if (p != Point64{}) d.push_back(p);
  }
  return star_from_directions(center, std::move(d));
}

// A valid set tiling part of a cells x cells grid of squares of side `cell` from `origin`:
// unit squares, 2x2 blocks (whose sides carry the vertices of smaller neighbours in their
// interior), squares cut into two triangles, some cells left empty, and sometimes a collinear
// vertex in the middle of a side (cell must be even). Neighbours share edges in opposite
// directions or touch at vertices.
template <class Draw>
PolygonSet random_grid_set(Draw& draw, int cells, std::int64_t cell, Point64 origin) {
  std::vector<char> used(static_cast<std::size_t>(cells * cells), 0);
  auto at = [&](int i, int j) -> char& { return used[static_cast<std::size_t>(j * cells + i)]; };
  auto corner = [&](int i, int j) { return Point64{origin.x + i * cell, origin.y + j * cell}; };
  PolygonSet set;
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      if (at(i, j)) continue;
      const auto kind = draw(0, 10);
      int size = 1;
      if (kind == 1 && i + 1 < cells && j + 1 < cells && !at(i + 1, j) && !at(i, j + 1) &&
          !at(i + 1, j + 1)) {
        size = 2;
      }
      for (int dj = 0; dj < size; ++dj)
        for (int di = 0; di < size; ++di) at(i + di, j + dj) = 1;
      if (kind == 0) continue;  // an empty cell
      const Point64 a = corner(i, j), b = corner(i + size, j), c = corner(i + size, j + size),
                    d = corner(i, j + size);
      if (kind == 2 || kind == 3) {  // two triangles along one diagonal
        if (kind == 2) {
          set.push_back({a, b, c});
          set.push_back({a, c, d});
        } else {
          set.push_back({a, b, d});
          set.push_back({b, c, d});
        }
        continue;
      }
      Ring r;
      const Point64 corners[4] = {a, b, c, d};
      for (int k = 0; k < 4; ++k) {
        r.push_back(corners[k]);
        if (cell % 2 == 0 && draw(0, 4) == 0) {
          const Point64 n = corners[(k + 1) % 4];
          r.push_back({(corners[k].x + n.x) / 2, (corners[k].y + n.y) / 2});
        }
      }
      set.push_back(r);
    }
  }
  return set;
}

// The points of the grid [0, w) x [0, h), row by row (for bounded-exhaustive checks).
inline std::vector<Point64> grid_points(std::int64_t w, std::int64_t h) {
  std::vector<Point64> out;
  for (std::int64_t y = 0; y < h; ++y)
    for (std::int64_t x = 0; x < w; ++x) out.push_back({x, y});
  return out;
}

// All counter-clockwise triangles with area on the grid [0, w) x [0, h).
inline std::vector<Polygon> grid_triangles(std::int64_t w, std::int64_t h) {
  const std::vector<Point64> g = grid_points(w, h);
  std::vector<Polygon> triangles;
  for (std::size_t i = 0; i < g.size(); ++i)
    for (std::size_t j = i + 1; j < g.size(); ++j)
      for (std::size_t k = j + 1; k < g.size(); ++k) {
        Polygon t{g[i], g[j], g[k]};
        const __int128 area = __int128(t[1].x - t[0].x) * (t[2].y - t[0].y) -
                              __int128(t[1].y - t[0].y) * (t[2].x - t[0].x);
        if (area == 0) continue;
        if (area < 0) std::swap(t[1], t[2]);
        triangles.push_back(t);
      }
  return triangles;
}

// Calls f(ring) for each of the g.size()^k rings of k vertices taken from g (repeats allowed).
template <class F>
void for_each_ring(const std::vector<Point64>& g, std::size_t k, F&& f) {
  Ring ring(k);
  std::vector<std::size_t> at(k, 0);
  while (true) {
    for (std::size_t i = 0; i < k; ++i) ring[i] = g[at[i]];
    f(ring);
    std::size_t i = k;
    while (i > 0 && ++at[i - 1] == g.size()) at[--i] = 0;
    if (i == 0) return;
  }
}

}  // namespace edgeland::testing
