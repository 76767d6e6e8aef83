#include "labeling.hpp"

#include <algorithm>
#include <memory>
#include <utility>

#include "edgeland/kernel/angle.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland::detail {
namespace {

// Crossing half-edge h from its right side to its left side.
SideState cross(const PlaneGraph& g, LabelMode mode, SideState s, std::uint32_t h) {
  const std::uint32_t e = h >> 1;
  const std::int32_t dir = (h & 1) ? -1 : 1;
  if (mode == LabelMode::kWinding) {
    for (std::uint32_t k = g.mult_begin[e]; k < g.mult_begin[e + 1]; ++k)
      s.s[0] += dir * g.mults[k].net;
    return s;
  }
  for (std::uint8_t c = 0; c < 2; ++c) {
    std::int32_t entering = -1;
    bool leaves_current = false;
    for (std::uint32_t k = g.mult_begin[e]; k < g.mult_begin[e + 1]; ++k) {
      const Multiplicity& m = g.mults[k];
      if (m.channel != c) continue;
      const std::int32_t net = dir * m.net;
      if (net > 0 && entering < 0) entering = m.polygon;  // mults are sorted by polygon
      if (net < 0 && m.polygon == s.s[c]) leaves_current = true;
    }
    if (entering >= 0) s.s[c] = entering;
    else if (leaves_current) s.s[c] = -1;
  }
  return s;
}

std::uint32_t around_count(const PlaneGraph& g, std::uint32_t v) {
  return g.around_begin[v + 1] - g.around_begin[v];
}

Point64 direction(const PlaneGraph& g, std::uint32_t h) {
  const Point64 o = g.vertices[g.origin(h)], t = g.vertices[g.target(h)];
  return {t.x - o.x, t.y - o.y};
}

// Position (in g.around) of the half-edge whose counter-clockwise sector contains direction d
// (d must not be the direction of a half-edge at v).
std::uint32_t sector_containing(const PlaneGraph& g, std::uint32_t v, Point64 d) {
  const std::uint32_t b = g.around_begin[v], e = g.around_begin[v + 1];
  std::uint32_t last_before = e;  // the last half-edge with angle < angle(d)
  for (std::uint32_t k = b; k < e; ++k)
    if (angle_less(direction(g, g.around[k]), d)) last_before = k;
  return last_before == e ? e - 1 : last_before;
}

// Which edges span a given x: a segment tree over the distinct vertex x coordinates.
class XStabbing {
 public:
  explicit XStabbing(const PlaneGraph& g) : g_(g) {
    for (const Point64& p : g.vertices)
      if (xs_.empty() || xs_.back() != p.x) xs_.push_back(p.x);
    size_ = 1;
    while (size_ < 2 * xs_.size()) size_ <<= 1;
    nodes_.resize(2 * size_);
    for (std::uint32_t e = 0; e < g.edge_count(); ++e)
      insert(e, 2 * slot(g.vertices[g.from[e]].x), 2 * slot(g.vertices[g.to[e]].x));
  }
  template <class F>
  void for_each_spanning(std::int64_t x, F&& f) const {
    for (std::size_t n = size_ + 2 * slot(x); n >= 1; n >>= 1)
      for (std::uint32_t e : nodes_[n]) f(e);
  }

 private:
  std::size_t slot(std::int64_t x) const {
    return static_cast<std::size_t>(std::lower_bound(xs_.begin(), xs_.end(), x) - xs_.begin());
  }
  void insert(std::uint32_t e, std::size_t lo, std::size_t hi) {  // inclusive slots
    for (std::size_t l = lo + size_, r = hi + size_ + 1; l < r; l >>= 1, r >>= 1) {
      if (l & 1) nodes_[l++].push_back(e);
      if (r & 1) nodes_[--r].push_back(e);
    }
  }
  const PlaneGraph& g_;
  std::vector<std::int64_t> xs_;
  std::size_t size_ = 1;
  std::vector<std::vector<std::uint32_t>> nodes_;
};

// The highest feature of the labeled part of the graph directly below vertex p: an edge
// interior or a vertex. Heights are compared exactly as fractions num / den, den > 0.
struct Below {
  bool found = false;
  bool is_vertex = false;
  std::uint32_t id = 0;  // vertex id or edge id
  Int128 num = 0, den = 1;
};

Below find_below(const PlaneGraph& g, const XStabbing& stab, const std::vector<bool>& labeled,
                 Point64 p) {
  Below best;
  auto offer = [&](bool is_vertex, std::uint32_t id, Int128 num, Int128 den) {
    if (best.found && num * best.den <= best.num * den) return;
    best = {true, is_vertex, id, num, den};
  };
  stab.for_each_spanning(p.x, [&](std::uint32_t e) {
    if (!labeled[g.from[e]]) return;
    const Point64 a = g.vertices[g.from[e]], b = g.vertices[g.to[e]];
    if (a.x == b.x) {  // vertical: its top end (b) is the candidate
      if (b.y < p.y) offer(true, g.to[e], b.y, 1);
      return;
    }
    if (a.x == p.x) {
      if (a.y < p.y) offer(true, g.from[e], a.y, 1);
      return;
    }
    if (b.x == p.x) {
      if (b.y < p.y) offer(true, g.to[e], b.y, 1);
      return;
    }
    if (orientation(a, b, p) != Orientation::kCounterClockwise) return;  // not below p
    const Int128 dx = b.x - a.x;
    offer(false, e, Int128(a.y) * dx + Int128(b.y - a.y) * (p.x - a.x), dx);
  });
  return best;
}

}  // namespace

SideState empty_state(LabelMode mode) {
  SideState s;
  if (mode == LabelMode::kWinding) s.s = {0, 0};
  return s;
}

std::vector<SideState> label_sides(const PlaneGraph& g, LabelMode mode) {
  const std::size_t nv = g.vertices.size();
  std::vector<SideState> left(2 * g.edge_count(), empty_state(mode));
  std::vector<bool> visited(nv, false);
  std::unique_ptr<XStabbing> stab;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> queue;  // (vertex, known position)
  bool any_labeled = false;

  for (std::uint32_t v0 = 0; v0 < nv; ++v0) {
    if (visited[v0] || around_count(g, v0) == 0) continue;
    // v0 is the smallest vertex of a new component: west of it lies its outer face.
    SideState base = empty_state(mode);
    if (any_labeled) {
      if (!stab) stab = std::make_unique<XStabbing>(g);
      const Below below = find_below(g, *stab, visited, g.vertices[v0]);
      if (below.found && below.is_vertex) {
        base = left[g.around[sector_containing(g, below.id, {0, 1})]];
      } else if (below.found) {
        base = left[2 * below.id];  // from -> to runs east: its left side is above
      }
    }
    const std::uint32_t k0 = sector_containing(g, v0, {-1, 0});
    left[g.around[k0]] = base;
    visited[v0] = true;
    queue.assign(1, {v0, k0});
    while (!queue.empty()) {
      const auto [w, k] = queue.back();
      queue.pop_back();
      const std::uint32_t b = g.around_begin[w], n = around_count(g, w);
      // Rotate counter-clockwise from the known sector, crossing one half-edge at a time.
      for (std::uint32_t i = 1; i < n; ++i) {
        const std::uint32_t prev = b + (k - b + i - 1) % n, cur = b + (k - b + i) % n;
        left[g.around[cur]] = cross(g, mode, left[g.around[prev]], g.around[cur]);
      }
      // Carry each side along its edge: the left of h is the right of its twin.
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t h = g.around[b + i], twin = h ^ 1, x = g.origin(twin);
        if (visited[x]) continue;
        visited[x] = true;
        const std::uint32_t bx = g.around_begin[x], nx = around_count(g, x);
        const std::uint32_t before = bx + (g.position_of[twin] - bx + nx - 1) % nx;
        left[g.around[before]] = left[h];
        queue.emplace_back(x, before);
      }
    }
    any_labeled = true;
  }
  return left;
}

}  // namespace edgeland::detail
