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

// Inside the box and on none of its sides: every quadrant around p is the cell's.
bool strictly_inside(const Box64& box, Point64 p) {
  return box.min.x < p.x && p.x < box.max.x && box.min.y < p.y && p.y < box.max.y;
}

// For each segment, the one that follows it in the cell (scratch.next), or kNoSegment.
// scratch.order sorts the segments by start point.
void successors(std::span<const SurfaceSegment> segs, const Box64& cell, const Box64& world,
                bool border_wall, TraceScratch& scratch) {
  const std::vector<std::size_t>& order = scratch.order;
  std::vector<std::size_t>& next = scratch.next;
  std::vector<Point64>& dirs = scratch.directions;
  next.assign(segs.size(), kNoSegment);
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const Point64 v = segs[i].b;
    const auto first = std::lower_bound(order.begin(), order.end(), v,
                                        [&](std::size_t s, Point64 p) { return segs[s].a < p; });
    auto last = first;
    while (last != order.end() && segs[*last].a == v) ++last;
    if (first == last) continue;
    if (last - first == 1 && strictly_inside(cell, v)) {  // nothing blocked: the one way on
      next[i] = *first;
      continue;
    }
    dirs.clear();
    for (auto it = first; it != last; ++it) dirs.push_back(minus(segs[*it].b, v));
    const auto pick = first_clockwise(minus(segs[i].a, v), dirs,
                                      quadrants_not_in_cell(cell, world, border_wall, v));
    if (pick) next[i] = *(first + static_cast<std::ptrdiff_t>(*pick));
  }
}

// Follows `next` from segment `start`, marking segments used; stops at the end of the chain or
// back at a used segment (the start of a cycle).
// The segments follow() will take from `start`, or more (at most all of them): the chain's
// arrays are allocated once, at their size.
std::size_t length_from(const std::vector<std::size_t>& next, std::size_t start,
                        const std::vector<std::uint8_t>& used) {
  std::size_t n = 0;
  for (std::size_t s = start; s != kNoSegment && !used[s] && n < next.size(); s = next[s]) {
    ++n;
    if (next[s] == start) break;
  }
  return n;
}

TracedChain follow(std::span<const SurfaceSegment> segs, const std::vector<std::size_t>& next,
                   std::size_t start, std::vector<std::uint8_t>& used) {
  TracedChain chain;
  const std::size_t length = length_from(next, start, used);
  chain.points.reserve(length + 1);
  chain.materials.reserve(length);
  chain.points.push_back(segs[start].a);
  std::size_t s = start;
  while (s != kNoSegment && !used[s]) {
    used[s] = 1;
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

// In place: point i is read (with its neighbours) before anything at or after it is written,
// except the first point, which the last one of a closed chain reads: it is kept aside.
void drop_straight_points(TracedChain& chain) {
  const std::size_t n = chain.points.size();
  if (n < 3) return;
  std::vector<Point64>& points = chain.points;
  std::vector<Material>& materials = chain.materials;
  const Point64 first_point = points[0];
  const Material last_material = materials[(n - 1) % materials.size()];
  Point64 before_point = points[n - 1];
  Material before_material = last_material;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 at = points[i];
    const Point64 after = i + 1 < n ? points[i + 1] : first_point;
    const Material material = i < materials.size() ? materials[i] : last_material;
    const bool end = !chain.closed && (i == 0 || i + 1 == n);
    const bool straight = !end && before_material == material &&
                          orientation(before_point, at, after) == Orientation::kCollinear;
    before_point = at;
    before_material = material;
    if (straight) continue;
    points[kept] = at;
    if (i < materials.size()) materials[kept] = material;
    ++kept;
  }
  points.resize(kept);
  materials.resize(chain.closed ? kept : kept - 1);
}

}  // namespace

void trace_chains(std::span<const SurfaceSegment> segs, const Box64& cell, const Box64& world,
                  bool border_wall, TraceScratch& scratch, std::vector<TracedChain>& out) {
  std::vector<std::size_t>& order = scratch.order;
  order.resize(segs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t l, std::size_t r) {
    return segs[l].a < segs[r].a || (segs[l].a == segs[r].a && segs[l].b < segs[r].b);
  });
  successors(segs, cell, world, border_wall, scratch);
  scratch.has_previous.assign(segs.size(), 0);
  scratch.used.assign(segs.size(), 0);
  for (std::size_t s : scratch.next)
    if (s != kNoSegment) scratch.has_previous[s] = 1;
  const std::size_t first = out.size();
  for (std::size_t s : order)
    if (!scratch.has_previous[s]) out.push_back(follow(segs, scratch.next, s, scratch.used));
  for (std::size_t s : order)
    if (!scratch.used[s]) out.push_back(follow(segs, scratch.next, s, scratch.used));
  for (std::size_t k = first; k < out.size(); ++k) make_canonical(out[k]);
}

}  // namespace edgeland::game_detail
