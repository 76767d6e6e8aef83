// Test polygons for triangulate() and convex_pieces() (piece_shapes.hpp).
#include "piece_shapes.hpp"

#include <map>

namespace edgeland::testing {
namespace {

__int128 cross(Point64 o, Point64 a, Point64 b) {
  return __int128(a.x - o.x) * (b.y - o.y) - __int128(a.y - o.y) * (b.x - o.x);
}

bool has(const std::set<Cell>& cells, std::int64_t x, std::int64_t y) {
  return cells.count({x, y}) != 0;
}

// The unit boundary edges with the region on their left, keyed by start point.
std::multimap<Point64, Point64> boundary_edges(const std::set<Cell>& cells) {
  std::multimap<Point64, Point64> edges;
  for (const auto& [x, y] : cells) {
    if (!has(cells, x, y - 1)) edges.insert({{x, y}, {x + 1, y}});
    if (!has(cells, x + 1, y)) edges.insert({{x + 1, y}, {x + 1, y + 1}});
    if (!has(cells, x, y + 1)) edges.insert({{x + 1, y + 1}, {x, y + 1}});
    if (!has(cells, x - 1, y)) edges.insert({{x, y + 1}, {x, y}});
  }
  return edges;
}

}  // namespace

std::optional<Polygon> polyomino_boundary(const std::set<Cell>& cells, std::int64_t scale) {
  const std::multimap<Point64, Point64> edges = boundary_edges(cells);
  if (edges.empty()) return std::nullopt;
  for (auto it = edges.begin(); it != edges.end(); ++it)
    if (edges.count(it->first) != 1) return std::nullopt;  // two cells meet at a corner only
  Polygon ring;
  Point64 at = edges.begin()->first;
  do {
    ring.push_back({at.x * scale, at.y * scale});
    at = edges.find(at)->second;
  } while (at != edges.begin()->first && ring.size() <= edges.size());
  if (ring.size() != edges.size()) return std::nullopt;  // a hole or a second component
  return ring;
}

Polygon without_straight_vertices(const Polygon& ring) {
  Polygon out;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
    if (cross(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]) != 0) out.push_back(ring[i]);
  return out;
}

std::set<Cell> spiral_cells(int turns) {
  // Arms at distance 2 apart: leg k has length 2 * (k / 2 + 1), turning left after each leg.
  std::set<Cell> cells{{0, 0}};
  static constexpr std::int64_t kDir[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  std::int64_t x = 0, y = 0;
  for (int k = 0; k < turns; ++k) {
    const std::int64_t length = 2 * (k / 2 + 1);
    for (std::int64_t s = 0; s < length; ++s) {
      x += kDir[k % 4][0];
      y += kDir[k % 4][1];
      cells.insert({x, y});
    }
  }
  return cells;
}

Polygon unit_comb(std::int64_t teeth, std::int64_t height) {
  const std::int64_t width = 2 * teeth + 1;
  Polygon p{{0, 0}, {width, 0}, {width, 1}};
  for (std::int64_t k = teeth - 1; k >= 0; --k) {
    const std::int64_t x = 2 * k + 1;
    p.push_back({x + 1, 1});
    p.push_back({x + 1, 1 + height});
    p.push_back({x, 1 + height});
    p.push_back({x, 1});
  }
  p.push_back({0, 1});
  return p;
}

Polygon zigzag_band(std::int64_t teeth) {
  // Bottom: notches up to y = 3 between feet at y = 0; top: notches down to y = 5 from y = 8,
  // shifted by half a period.
  Polygon p;
  for (std::int64_t k = 0; k <= teeth; ++k) {
    p.push_back({4 * k, 0});
    if (k < teeth) p.push_back({4 * k + 2, 3});
  }
  for (std::int64_t k = teeth; k >= 0; --k) {
    p.push_back({4 * k + 1, 8});
    if (k > 0) p.push_back({4 * k - 1, 5});
  }
  return p;
}

bool makes_corner_touch(const std::set<Cell>& cells, Cell c) {
  const auto [x, y] = c;
  for (const std::int64_t dx : {-1, 1}) {
    for (const std::int64_t dy : {-1, 1}) {
      // The block of c, its diagonal neighbour and the two cells beside both.
      if (has(cells, x + dx, y + dy) && !has(cells, x + dx, y) && !has(cells, x, y + dy))
        return true;
    }
  }
  return false;
}

}  // namespace edgeland::testing
