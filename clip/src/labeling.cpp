#include "labeling.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "edgeland/kernel/angle.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/ray.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "offsets.hpp"

namespace edgeland::detail {
namespace {

// The owner of one channel after crossing, from the right, the edge's multiplicities of that
// channel in [first, last) (net counted along the half-edge crossed).
std::int32_t owner_after(const PlaneGraph& g, std::int32_t dir, std::uint8_t channel,
                         std::int32_t owner, std::uint32_t first, std::uint32_t last) {
  std::int32_t entering = -1;
  bool leaves_current = false;
  for (std::uint32_t k = first; k < last; ++k) {
    const Multiplicity& m = g.mults[k];
    if (m.channel != channel) continue;
    const std::int32_t net = dir * m.net;
    if (net > 0 && entering < 0) entering = m.polygon;  // mults are sorted by polygon
    if (net < 0 && m.polygon == owner) leaves_current = true;
  }
  return entering >= 0 ? entering : leaves_current ? -1 : owner;
}

// Crossing half-edge h from its right side to its left side. The two channels are kept in
// separate locals and the state built once at the end: writing one 4-byte half of the state
// and then reading it whole defeats store forwarding, which made this line most of labeling.
SideState cross(const PlaneGraph& g, LabelMode mode, SideState s, std::uint32_t h) {
  const std::uint32_t e = h >> 1;
  const std::int32_t dir = (h & 1) ? -1 : 1;
  const std::uint32_t first = g.mult_begin[e], last = g.mult_begin[e + 1];
  std::int32_t s0 = s.by_channel[0], s1 = s.by_channel[1];
  if (mode == LabelMode::kWinding) {
    for (std::uint32_t k = first; k < last; ++k) s0 += dir * g.mults[k].net;
  } else if (mode == LabelMode::kOwnerAndCount) {
    s0 = owner_after(g, dir, kSubjectChannel, s0, first, last);
    for (std::uint32_t k = first; k < last; ++k)
      if (g.mults[k].channel == kClipChannel) s1 += dir * g.mults[k].net;
  } else if (last - first == 1) {
    // One polygon's edge, the common case: owner_after for its channel, the other unchanged.
    const Multiplicity& m = g.mults[first];
    const std::int32_t net = dir * m.net;
    auto after = [&](std::int32_t owner) {
      return net > 0 ? m.polygon : owner == m.polygon ? -1 : owner;
    };
    if (m.channel == kSubjectChannel)
      s0 = after(s0);
    else
      s1 = after(s1);
  } else {
    s0 = owner_after(g, dir, kSubjectChannel, s0, first, last);
    s1 = owner_after(g, dir, kClipChannel, s1, first, last);
  }
  SideState out;
  out.by_channel = {s0, s1};
  return out;
}

// Whether crossing half-edge h from its right side (state `right`) to its left keeps each
// channel covered at most once, by the polygon its state names (label_sides' check). Per
// channel: at most one polygon enters and at most one leaves, each by exactly one edge; one
// that leaves must be the current owner; one that enters alone needs no current owner.
bool keeps_single_cover(const PlaneGraph& g, std::uint32_t h, const SideState& right) {
  const std::uint32_t e = h >> 1;
  const std::int32_t dir = (h & 1) ? -1 : 1;
  const std::uint32_t first = g.mult_begin[e], last = g.mult_begin[e + 1];
  if (last - first == 1) {  // one polygon's edge, the common case: the rule below, unrolled
    const Multiplicity& m = g.mults[first];
    const std::int32_t net = dir * m.net;
    if (m.channel > kClipChannel) return false;
    const std::int32_t owner = right.by_channel[m.channel];
    return net == 1 ? owner < 0 : net == -1 && owner == m.polygon;
  }
  std::int32_t entering[2] = {-1, -1}, leaving[2] = {-1, -1};
  for (std::uint32_t k = first; k < last; ++k) {
    const Multiplicity& m = g.mults[k];
    const std::int32_t net = dir * m.net;
    if ((net != 1 && net != -1) || m.channel > kClipChannel) return false;
    std::int32_t& slot = net > 0 ? entering[m.channel] : leaving[m.channel];
    if (slot >= 0) return false;
    slot = m.polygon;
  }
  for (int c = 0; c < 2; ++c) {
    const std::int32_t owner = right.by_channel[c];
    if (leaving[c] >= 0 ? leaving[c] != owner : entering[c] >= 0 && owner >= 0) return false;
  }
  return true;
}

std::uint32_t around_count(const PlaneGraph& g, std::uint32_t v) {
  return g.around_begin[v + 1] - g.around_begin[v];
}

Point64 direction(const PlaneGraph& g, std::uint32_t h) {
  const Point64 o = g.vertices[g.origin(h)], t = g.first_step(h);
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

// One straight piece of an edge's polyline: points i and i + 1 of edge e (from -> to order).
struct EdgeStretch {
  Point64 a, b;
  std::uint32_t edge, index;
  bool a_is_vertex, b_is_vertex;
};

void stretches_of(const PlaneGraph& g, std::vector<EdgeStretch>& out) {
  out.clear();
  out.reserve(2 * g.edge_count());
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    Point64 at = g.vertices[g.from(e)];
    const std::uint32_t m = g.interior_count(e);
    for (std::uint32_t i = 0; i <= m; ++i) {
      const Point64 nx = i < m ? g.interior_point(e, i) : g.vertices[g.to(e)];
      out.push_back({at, nx, e, i, i == 0, i == m});
      at = nx;
    }
  }
}

// Which pieces span a given x: a segment tree over the distinct x coordinates of their ends.
// Its nodes' lists are one array (CSR, offsets.hpp), filled in two passes over the pieces: a
// vector per node cost hundreds of allocations per call on a cell with a few islands.
class XStabbing {
 public:
  explicit XStabbing(const std::vector<EdgeStretch>& pieces) {
    for (const EdgeStretch& p : pieces) {
      xs_.push_back(p.a.x);
      xs_.push_back(p.b.x);
    }
    std::sort(xs_.begin(), xs_.end());
    xs_.erase(std::unique(xs_.begin(), xs_.end()), xs_.end());
    size_ = 1;
    while (size_ < 2 * xs_.size()) size_ <<= 1;
    begin_.assign(2 * size_ + 1, 0);
    for_each_insertion(pieces, [&](std::size_t node, std::uint32_t) { ++begin_[node + 1]; });
    add_up_counts(begin_);
    items_.resize(begin_.back());
    ScratchVector<std::uint32_t> at;
    at.assign(begin_.begin(), begin_.end() - 1);
    for_each_insertion(pieces, [&](std::size_t node, std::uint32_t k) { items_[at[node]++] = k; });
  }
  template <class F>
  void for_each_spanning(std::int64_t x, F&& f) const {
    for (std::size_t n = size_ + 2 * slot(x); n >= 1; n >>= 1)
      for (std::uint32_t i = begin_[n]; i < begin_[n + 1]; ++i) f(items_[i]);
  }

 private:
  std::size_t slot(std::int64_t x) const {
    return static_cast<std::size_t>(std::lower_bound(xs_.begin(), xs_.end(), x) - xs_.begin());
  }
  // visit(node, k) for every node piece k is listed in, pieces in order.
  template <class F>
  void for_each_insertion(const std::vector<EdgeStretch>& pieces, F&& visit) const {
    for (std::uint32_t k = 0; k < pieces.size(); ++k) {
      const std::size_t sa = slot(pieces[k].a.x), sb = slot(pieces[k].b.x);
      const std::size_t lo = 2 * std::min(sa, sb), hi = 2 * std::max(sa, sb);  // inclusive
      for (std::size_t l = lo + size_, r = hi + size_ + 1; l < r; l >>= 1, r >>= 1) {
        if (l & 1) visit(l++, k);
        if (r & 1) visit(--r, k);
      }
    }
  }
  ScratchVector<std::int64_t> xs_;
  std::size_t size_ = 1;
  ScratchVector<std::uint32_t> begin_, items_;
};

// The highest feature of the labeled part of the graph directly below point p, and the state
// just above it.
struct Below {
  bool found = false;
  SideState above;
};

// The state just above point q, where q is point `index` (0 < index <= interior count) of edge
// e's polyline or, for index 0 or the last, a vertex: the side of the polyline that (0, 1)
// points into at q.
SideState state_above_point(const PlaneGraph& g, const std::vector<SideState>& left,
                            const EdgeStretch& piece, bool at_a) {
  if (at_a ? piece.a_is_vertex : piece.b_is_vertex) {
    const std::uint32_t v = at_a ? g.from(piece.edge) : g.to(piece.edge);
    return left[g.around[sector_containing(g, v, {0, 1})]];
  }
  // An interior point: its neighbours along the edge, from -> to.
  const std::uint32_t e = piece.edge, i = at_a ? piece.index : piece.index + 1;
  const Point64 q = at_a ? piece.a : piece.b;
  const Point64 prev = i == 1 ? g.vertices[g.from(e)] : g.interior_point(e, i - 2);
  const Point64 nx = i == g.interior_count(e) ? g.vertices[g.to(e)] : g.interior_point(e, i);
  // Walking prev -> q -> nx, the left side at q is swept counter-clockwise from nx to prev.
  const bool left_side =
      strictly_inside_ccw_sector({nx.x - q.x, nx.y - q.y}, {prev.x - q.x, prev.y - q.y}, {0, 1});
  return left[left_side ? 2 * e : 2 * e + 1];
}

// `stab` may be null: then every piece is looked at (cheaper than building the tree for a few
// queries).
Below find_below(const PlaneGraph& g, const std::vector<EdgeStretch>& pieces, const XStabbing* stab,
                 const std::vector<std::uint8_t>& labeled, const std::vector<SideState>& left,
                 Point64 p) {
  NearestHit nearest(Ray{p, 0, -1}, NearestHit::Origin::kExcluded);
  const EdgeStretch* best = nullptr;
  auto consider = [&](std::uint32_t k) {
    const EdgeStretch& piece = pieces[k];
    if (labeled[g.from(piece.edge)] &&
        nearest.offer({piece.a, piece.b}) == NearestHit::Offer::kNearest)
      best = &piece;
  };
  if (stab) {
    stab->for_each_spanning(p.x, consider);
  } else {
    for (std::uint32_t k = 0; k < pieces.size(); ++k)
      if (std::min(pieces[k].a.x, pieces[k].b.x) <= p.x &&
          p.x <= std::max(pieces[k].a.x, pieces[k].b.x))
        consider(k);
  }
  if (!best) return {};
  // The hit is strictly below p (pieces through p are passed over; none is expected, as
  // components are disjoint): at an end of the piece (a vertical piece is met at its top) or
  // inside it.
  const RationalPoint at = nearest.point();
  if (is_exactly(at, best->a)) return {true, state_above_point(g, left, *best, true)};
  if (is_exactly(at, best->b)) return {true, state_above_point(g, left, *best, false)};
  // Running east (a -> b with a.x < b.x), the piece's left side is above it.
  const std::uint32_t e = best->edge;
  return {true, left[best->a.x < best->b.x ? 2 * e : 2 * e + 1]};
}

}  // namespace

SideState empty_state(LabelMode mode) {
  SideState s;
  if (mode == LabelMode::kWinding) s.by_channel = {0, 0};
  if (mode == LabelMode::kOwnerAndCount) s.by_channel = {-1, 0};
  return s;
}

bool label_sides(const PlaneGraph& g, LabelMode mode, std::vector<SideState>& left,
                 bool check_single_cover) {
  const std::size_t nv = g.vertices.size();
  left.assign(2 * g.edge_count(), empty_state(mode));
  ScratchVector<std::uint8_t> visited;  // bytes: no bit masking
  visited.assign(nv, 0);
  std::optional<XStabbing> stab;
  ScratchVector<EdgeStretch> pieces;
  constexpr int kScansBeforeTree = 4;
  int located = 0;
  // (vertex, known position)
  ScratchVector<std::pair<std::uint32_t, std::uint32_t>> queue;
  bool any_labeled = false;

  for (std::uint32_t v0 = 0; v0 < nv; ++v0) {
    if (visited[v0] || around_count(g, v0) == 0) continue;
    // v0 is the smallest vertex of a new component: west of it lies its outer face.
    SideState base = empty_state(mode);
    if (any_labeled) {
      // A few components are located by scanning every piece; from the fifth on, a segment
      // tree pays for itself.
      if (pieces.empty()) stretches_of(g, pieces);
      if (!stab && ++located > kScansBeforeTree) stab.emplace(pieces);
      const Below below =
          find_below(g, pieces, stab ? &*stab : nullptr, visited, left, g.vertices[v0]);
      if (below.found) base = below.above;
    }
    const std::uint32_t k0 = sector_containing(g, v0, {-1, 0});
    left[g.around[k0]] = base;
    visited[v0] = 1;
    queue.assign(1, {v0, k0});
    while (!queue.empty()) {
      const auto [w, k] = queue.back();
      queue.pop_back();
      const std::uint32_t b = g.around_begin[w], n = around_count(g, w);
      // Rotate counter-clockwise from the known sector, crossing one half-edge at a time.
      // (Positions wrap by a compare, not %: a division per step was a quarter of labeling.)
      for (std::uint32_t i = 1, prev = k; i < n; ++i) {
        const std::uint32_t cur = prev + 1 == b + n ? b : prev + 1;
        const SideState right = left[g.around[prev]];
        if (check_single_cover && !keeps_single_cover(g, g.around[cur], right)) return false;
        left[g.around[cur]] = cross(g, mode, right, g.around[cur]);
        prev = cur;
      }
      // Carry each side along its edge: the left of h is the right of its twin.
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t h = g.around[b + i], twin = h ^ 1, x = g.origin(twin);
        if (visited[x]) continue;
        visited[x] = 1;
        const std::uint32_t before = g.turn_at[h];  // at x, clockwise from the twin
        left[g.around[before]] = left[h];
        queue.emplace_back(x, before);
      }
    }
    any_labeled = true;
  }
  return true;
}

}  // namespace edgeland::detail
