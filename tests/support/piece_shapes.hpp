#pragma once
// Valid polygons for the triangulation and convex-decomposition tests (triangulate.hpp,
// convex_pieces.hpp): polyominoes whose boundaries keep every lattice point (long runs of
// collinear vertices, like the landscape's cell-cut pieces), spirals, combs, zigzags, sawtooth
// boxes. Written over a `draw(lo, hi)` callable returning an integer in [lo, hi) (RcDraw in
// properties, SplitMixDraw in the large deterministic tests); independent of the code under test.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::testing {

using Cell = std::pair<std::int64_t, std::int64_t>;  // unit square [x, x+1] x [y, y+1]

// The counter-clockwise boundary of a set of unit cells scaled by `scale` (every lattice point
// of the unscaled boundary a vertex, so straight vertices abound), or nullopt when it is not one
// strictly simple ring: cells touching only at a corner, holes, several components.
std::optional<Polygon> polyomino_boundary(const std::set<Cell>& cells, std::int64_t scale = 1);

// The boundary without its straight vertices.
Polygon without_straight_vertices(const Polygon& ring);

// A square spiral corridor one cell wide with walls one cell wide between its arms, `turns`
// quarter turns long: the cells of its path, for polyomino_boundary.
std::set<Cell> spiral_cells(int turns);

// A comb of `teeth` teeth one unit wide with one-unit gaps, height `height`, on a base bar one
// unit high: 4 * teeth + 4 vertices.
Polygon unit_comb(std::int64_t teeth, std::int64_t height);

// A zigzag band: `teeth` V-shaped notches on top and bottom, offset by half a period, so the
// sweep meets a split and a merge vertex per notch.
Polygon zigzag_band(std::int64_t teeth);

// The box [0, w] x [0, h] (w, h >= 2) with up to `per_side` extra vertices on each side, at
// distinct random positions (a landscape cell's piece whose sides carry its neighbours'
// vertices).
template <class Draw>
Polygon box_with_side_vertices(Draw& draw, std::int64_t w, std::int64_t h, std::size_t per_side);

// A polyomino grown from one cell by `count` random additions of neighbouring cells (an
// addition that would make two cells touch at a corner only is skipped); nullopt if the
// result has a hole.
template <class Draw>
std::optional<Polygon> random_polyomino(Draw& draw, std::size_t count, std::int64_t scale);

// --- templates ---

template <class Draw>
Polygon box_with_side_vertices(Draw& draw, std::int64_t w, std::int64_t h, std::size_t per_side) {
  // Up to per_side distinct positions: a bounded number of draws, so a constant draw (a fuzz
  // input that ran out of bytes) still ends.
  auto positions = [&](std::int64_t length) {
    std::set<std::int64_t> at;
    for (std::size_t k = 0; k < 4 * per_side && at.size() < per_side; ++k)
      at.insert(draw(1, length));
    return at;
  };
  Polygon p{{0, 0}};
  for (std::int64_t x : positions(w)) p.push_back({x, 0});
  p.push_back({w, 0});
  for (std::int64_t y : positions(h)) p.push_back({w, y});
  p.push_back({w, h});
  const auto top = positions(w);
  for (auto it = top.rbegin(); it != top.rend(); ++it) p.push_back({*it, h});
  p.push_back({0, h});
  const auto left = positions(h);
  for (auto it = left.rbegin(); it != left.rend(); ++it) p.push_back({0, *it});
  return p;
}

// Whether adding c makes a 2 x 2 block around one of c's corners hold only a diagonal pair.
bool makes_corner_touch(const std::set<Cell>& cells, Cell c);

template <class Draw>
std::optional<Polygon> random_polyomino(Draw& draw, std::size_t count, std::int64_t scale) {
  std::set<Cell> cells{{0, 0}};
  std::vector<Cell> list{{0, 0}};
  for (std::size_t attempt = 0; cells.size() < count && attempt < 20 * count; ++attempt) {
    const Cell from =
        list[static_cast<std::size_t>(draw(0, static_cast<std::int64_t>(list.size())))];
    static constexpr std::int64_t kStep[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    const auto* step = kStep[draw(0, 4)];
    const Cell c{from.first + step[0], from.second + step[1]};
    if (cells.count(c) != 0 || makes_corner_touch(cells, c)) continue;
    cells.insert(c);
    list.push_back(c);
  }
  return polyomino_boundary(cells, scale);
}

}  // namespace edgeland::testing
