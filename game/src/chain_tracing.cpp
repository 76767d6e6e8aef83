#include "chain_tracing.hpp"

#include <algorithm>
#include <optional>

#include "edgeland/kernel/predicates.hpp"

namespace edgeland::game_detail {
namespace {

constexpr std::size_t kNoSegment = static_cast<std::size_t>(-1);

// Whether the open quadrant (sx, sy) next to p lies in the interior of the closed box.
bool quadrant_inside(const Box64& box, Point64 p, int sx, int sy) {
  const bool x = sx > 0 ? box.min.x <= p.x && p.x < box.max.x : box.min.x < p.x && p.x <= box.max.x;
  const bool y = sy > 0 ? box.min.y <= p.y && p.y < box.max.y : box.min.y < p.y && p.y <= box.max.y;
  return x && y;
}

// Quadrant q (slot 2q + 1 of around_vertex.hpp) as signs.
constexpr int kSx[4] = {1, -1, -1, 1};
constexpr int kSy[4] = {1, 1, -1, -1};

Point64 minus(Point64 a, Point64 b) { return {a.x - b.x, a.y - b.y}; }

// For each segment, the one that follows it in the cell, or kNoSegment. `order` sorts the
// segments by start point.
std::vector<std::size_t> successors(const std::vector<SurfaceSegment>& segs,
                                    const std::vector<std::size_t>& order, const Box64& cell,
                                    const Box64& world, bool border_wall) {
  std::vector<std::size_t> next(segs.size(), kNoSegment);
  std::vector<Point64> dirs;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const Point64 v = segs[i].b;
    const auto first = std::lower_bound(order.begin(), order.end(), v,
                                        [&](std::size_t s, Point64 p) { return segs[s].a < p; });
    auto last = first;
    while (last != order.end() && segs[*last].a == v) ++last;
    if (first == last) continue;
    dirs.clear();
    for (auto it = first; it != last; ++it) dirs.push_back(minus(segs[*it].b, v));
    const auto pick = first_clockwise(minus(segs[i].a, v), dirs,
                                      quadrants_not_in_cell(cell, world, border_wall, v));
    if (pick) next[i] = *(first + static_cast<std::ptrdiff_t>(*pick));
  }
  return next;
}

// Follows `next` from segment `start`, marking segments used; stops at the end of the chain or
// back at a used segment (the start of a cycle).
TracedChain follow(const std::vector<SurfaceSegment>& segs, const std::vector<std::size_t>& next,
                   std::size_t start, std::vector<bool>& used) {
  TracedChain chain;
  chain.points.push_back(segs[start].a);
  std::size_t s = start;
  while (s != kNoSegment && !used[s]) {
    used[s] = true;
    chain.points.push_back(segs[s].b);
    chain.materials.push_back(segs[s].material);
    s = next[s];
  }
  chain.closed = s == start;
  if (chain.closed) chain.points.pop_back();
  return chain;
}

void drop_straight_points(TracedChain& chain);

void rotate_to_smallest(TracedChain& chain) {
  const auto smallest = std::min_element(chain.points.begin(), chain.points.end());
  const auto shift = smallest - chain.points.begin();
  std::rotate(chain.points.begin(), smallest, chain.points.end());
  std::rotate(chain.materials.begin(), chain.materials.begin() + shift, chain.materials.end());
}

}  // namespace

void make_canonical(TracedChain& chain) {
  drop_straight_points(chain);
  if (chain.closed) rotate_to_smallest(chain);
}

BlockedQuadrants quadrants_not_in_cell(const Box64& cell, const Box64& world, bool border_wall,
                                       Point64 p) {
  BlockedQuadrants blocked{};
  for (std::size_t q = 0; q < 4; ++q) {
    const bool mine = quadrant_inside(cell, p, kSx[q], kSy[q]) ||
                      (border_wall && !quadrant_inside(world, p, kSx[q], kSy[q]));
    blocked[q] = !mine;
  }
  return blocked;
}

BlockedQuadrants quadrants_outside_world(const Box64& world, bool border_wall, Point64 p) {
  BlockedQuadrants blocked{};
  for (std::size_t q = 0; q < 4; ++q)
    blocked[q] = !border_wall && !quadrant_inside(world, p, kSx[q], kSy[q]);
  return blocked;
}

namespace {

void drop_straight_points(TracedChain& chain) {
  const std::size_t n = chain.points.size();
  if (n < 3) return;
  std::vector<Point64> points;
  std::vector<Material> materials;
  for (std::size_t i = 0; i < n; ++i) {
    const bool end = !chain.closed && (i == 0 || i + 1 == n);
    const std::size_t before = (i + n - 1) % n;
    const bool straight = !end && chain.materials[before] == chain.materials[i] &&
                          orientation(chain.points[before], chain.points[i],
                                      chain.points[(i + 1) % n]) == Orientation::kCollinear;
    if (straight) continue;
    points.push_back(chain.points[i]);
    if (i < chain.materials.size()) materials.push_back(chain.materials[i]);
  }
  chain.points = std::move(points);
  chain.materials = std::move(materials);
}

}  // namespace

std::vector<TracedChain> trace_chains(std::vector<SurfaceSegment> segs, const Box64& cell,
                                      const Box64& world, bool border_wall) {
  std::vector<std::size_t> order(segs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t l, std::size_t r) {
    return segs[l].a < segs[r].a || (segs[l].a == segs[r].a && segs[l].b < segs[r].b);
  });
  const std::vector<std::size_t> next = successors(segs, order, cell, world, border_wall);
  std::vector<bool> has_previous(segs.size(), false), used(segs.size(), false);
  for (std::size_t s : next)
    if (s != kNoSegment) has_previous[s] = true;
  std::vector<TracedChain> out;
  for (std::size_t s : order)
    if (!has_previous[s]) out.push_back(follow(segs, next, s, used));
  for (std::size_t s : order)
    if (!used[s]) out.push_back(follow(segs, next, s, used));
  for (TracedChain& c : out) make_canonical(c);
  return out;
}

}  // namespace edgeland::game_detail
