#pragma once
// Private to validate_*.cpp: the plane sweep of the reporting checks, shared by the ring check
// (strict simplicity, validate_self_intersection.cpp) and the set check (disjoint interiors,
// validate_overlap.cpp). The fast path that only accepts has its own (validate_accept_sweep.cpp).
//
// Events are the edge endpoints in lexicographic (x, then y) order: a sweep line in x, tilted
// infinitesimally so that it meets the points of one vertical line from the bottom up. The
// status holds the edges cut by that line, ordered by y. It is only ever asked to place an
// edge that starts at the current event point q, or to locate q itself, so every order
// question is one exact orientation or cross-product sign in Int128; no rational y is formed.
// A vertical edge in the status always runs through q (it entered at its lower end, at or
// below q, and leaves at its upper end, at or above q), so it sorts by its direction: steepest.
//
// The order stays consistent as long as no two status edges cross at a point interior to both;
// touching at a point and collinear overlap keep it consistent. Both checks stop at the first
// crossing, which the Shamos-Hoey argument finds no later than the sweep reaches it: the edges
// through the leftmost crossing are adjacent in the status just before it, and every pair that
// becomes adjacent is tested.
//
// Complexity: O(n log n) for n edges, plus the size of the last event's neighbourhood when a
// check stops there.
#include <algorithm>
#include <cstddef>
#include <iterator>
#include <optional>
#include <set>
#include <vector>

#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/validate.hpp"
#include "node_arena.hpp"
#include "validate_event_sort.hpp"
#include "validate_exact.hpp"

namespace edgeland::detail {

// One ring edge as the sweep sees it: endpoints in sweep order, plus where it came from.
struct SweepEdge {
  Point64 left;         // lexicographically smaller end
  Point64 right;        // larger end; never equal to `left`
  std::size_t polygon;  // index of the ring in the caller's set
  std::size_t edge;     // index of the edge in its ring
  bool forward;         // the ring runs from `left` to `right` (rightward, or upward if vertical)
};

// Appends the edges of `ring` as polygon `polygon`. The ring has >= 3 vertices, all in range,
// and no zero-length edge.
void append_ring_edges(const Ring& ring, std::size_t polygon, std::vector<SweepEdge>& out);

// Puts edges in the order run_sweep needs: by left end.
void sort_for_sweep(std::vector<SweepEdge>& edges);

inline bool is_vertical(const SweepEdge& e) noexcept { return e.left.x == e.right.x; }

// Where an edge cut by the sweep line at q lies: -1 strictly below q, 0 through q, +1 strictly
// above q. Inline: the status asks this O(log n) times per event.
inline int side_of_point(const SweepEdge& t, Point64 q) noexcept {
  if (is_vertical(t)) return 0;
  // t runs rightward, so q left of t means q above it, i.e. t below q.
  return -orient_sign(t.left, t.right, q);
}

// Order of the directions in which two edges through a common point leave it to the right
// (upward if vertical): -1 when a leaves below b, +1 above, 0 when collinear. Vertical is
// steepest.
inline int compare_directions(const SweepEdge& a, const SweepEdge& b) noexcept {
  const bool av = is_vertical(a), bv = is_vertical(b);
  if (av || bv) return av == bv ? 0 : (av ? 1 : -1);
  // Both point rightward: b turning counter-clockwise from a means b leaves above a.
  return -cross_sign(coord_diff(a.right.x, a.left.x), coord_diff(a.right.y, a.left.y),
                     coord_diff(b.right.x, b.left.x), coord_diff(b.right.y, b.left.y));
}

// Stands for the event point in heterogeneous status look-ups.
struct EventProbe {};

// Strict weak order of the status at the current event point (see the file comment).
class StatusOrder {
 public:
  using is_transparent = void;
  StatusOrder(const SweepEdge* edges, const Point64* event) : edges_(edges), event_(event) {}

  bool operator()(std::size_t a, std::size_t b) const noexcept {
    if (a == b) return false;
    const int c = compare_at_event(edges_[a], edges_[b]);
    return c != 0 ? c < 0 : a < b;  // collinear edges: by index, fixed for their whole life
  }
  bool operator()(std::size_t a, EventProbe) const noexcept {
    return side_of_point(edges_[a], *event_) < 0;
  }
  bool operator()(EventProbe, std::size_t b) const noexcept {
    return side_of_point(edges_[b], *event_) > 0;
  }

 private:
  // At least one of a, b starts at the event point: std::set only compares the edge being
  // inserted with edges already there.
  int compare_at_event(const SweepEdge& a, const SweepEdge& b) const noexcept {
    const Point64 q = *event_;
    const bool a_new = a.left == q, b_new = b.left == q;
    if (a_new && b_new) return compare_directions(a, b);
    if (a_new) {
      const int s = side_of_point(b, q);
      return s != 0 ? -s : compare_directions(a, b);
    }
    // b is the new edge (the status never compares two old ones).
    const int s = side_of_point(a, q);
    return s != 0 ? s : compare_directions(a, b);
  }

  const SweepEdge* edges_;
  const Point64* event_;
};

// What the sweep tells a check at each event point q.
struct EventView {
  Point64 q;
  const std::vector<std::size_t>& ending;    // edges whose right end is q
  const std::vector<std::size_t>& through;   // status edges with q strictly inside, bottom-up
  const std::vector<std::size_t>& starting;  // edges whose left end is q
  std::size_t below;                         // status edge just below q, or kNone
};

// An edge endpoint in event order. (Only the fallback of run_sweep for 2^32 or more edges
// sorts these with operator<: not reached by tests.)
struct SweepEvent {
  Point64 at;
  std::size_t edge;
  friend bool operator<(const SweepEvent& a, const SweepEvent& b) noexcept {
    return a.at < b.at || (a.at == b.at && a.edge < b.edge);
  }
};

// The right ends of `edges` in event order (by point, equal points by edge).
inline std::vector<SweepEvent> right_ends_in_order(const std::vector<SweepEdge>& edges) {
  const std::size_t n = edges.size();
  std::vector<SweepEvent> ends(n);
  if (n < UINT32_MAX) {  // a stable sort of 64-bit keys
    const std::vector<KeyedVertex> order =
        sorted_by_point(n, [&](std::size_t i) { return edges[i].right; });
    for (std::size_t k = 0; k < n; ++k) ends[k] = {edges[order[k].vertex].right, order[k].vertex};
  } else {  // Not reached by tests: 2^32 edges do not fit 32-bit keys.
    for (std::size_t i = 0; i < n; ++i) ends[i] = {edges[i].right, i};
    std::sort(ends.begin(), ends.end());
  }
  return ends;
}

// After an event: the pairs of status edges that have just become neighbours, `below` and the
// lowest edge of `block` (the edges through or leaving q, bottom-up) or `above` when the block
// is empty, and the highest edge of the block and `above`. Either end may be kNone.
template <class Check>
std::optional<Violation> check_new_neighbours(std::size_t below,
                                              const std::vector<std::size_t>& block,
                                              std::size_t above, Check& check) {
  const std::size_t low = block.empty() ? above : block.front();
  if (below != kNone && low != kNone) {
    if (auto v = check.adjacent(below, low)) return v;
  }
  if (!block.empty() && above != kNone) return check.adjacent(block.back(), above);
  return std::nullopt;
}

// Runs the sweep over `edges`, asking `check` at each event:
//   check.at_event(view)            before the status changes at q;
//   check.after_event(q, block)     with the edges through or leaving q, bottom-up, after it;
//   check.adjacent(a, b)            for every pair that has just become neighbours (a below b).
// Each returns an optional Violation; the first one stops the sweep and is returned.
// `edges` must be sorted by their left ends (sort_for_sweep), which makes the start events
// the edges themselves in order and keeps the edges cut by the sweep line close in memory.
template <class Check>
std::optional<Violation> run_sweep(const std::vector<SweepEdge>& edges, Check& check) {
  const std::size_t n = edges.size();
  const std::vector<SweepEvent> ends = right_ends_in_order(edges);
  Point64 q{};
  // Status nodes come from one arena released at the end: no allocator call per event.
  NodeArena arena;
  using Status = std::set<std::size_t, StatusOrder, ArenaAllocator<std::size_t>>;
  Status status(StatusOrder(edges.data(), &q), ArenaAllocator<std::size_t>(&arena));
  std::vector<Status::iterator> handle(n, status.end());
  std::vector<std::size_t> ending, through, starting, block;
  const auto through_q = [&](std::size_t e) { return side_of_point(edges[e], q) == 0; };

  std::size_t si = 0, ei = 0;
  while (si < n || ei < n) {
    // Every edge ends after it starts, so an edge ending at q has already been inserted.
    q = si < n && (ei == n || edges[si].left < ends[ei].at) ? edges[si].left : ends[ei].at;
    ending.clear();
    starting.clear();
    through.clear();
    for (; ei < n && ends[ei].at == q; ++ei) ending.push_back(ends[ei].edge);
    for (; si < n && edges[si].left == q; ++si) starting.push_back(si);

    // The status edges through q form one run; the ones not ending here pass through. An
    // edge ending here is in the run, so the run is found from it without a search.
    auto it = status.end();
    if (!ending.empty()) {
      it = handle[ending.front()];
      while (it != status.begin() && through_q(*std::prev(it))) --it;
    } else {
      it = status.lower_bound(EventProbe{});
    }
    const std::size_t below = it == status.begin() ? kNone : *std::prev(it);
    for (; it != status.end() && through_q(*it); ++it) {
      if (edges[*it].right != q) through.push_back(*it);
    }
    const auto above_it = it;  // not through q, so neither erased nor moved below

    if (auto v = check.at_event(EventView{q, ending, through, starting, below})) return v;

    for (const std::size_t e : ending) status.erase(handle[e]);
    // Bottom-up, each new edge lands just before the edge above q unless edges pass through
    // q: then the hint is wrong and the set searches as usual.
    std::sort(starting.begin(), starting.end(), [&](std::size_t a, std::size_t b) {
      const int c = compare_directions(edges[a], edges[b]);
      return c != 0 ? c < 0 : a < b;
    });
    for (const std::size_t s : starting) handle[s] = status.insert(above_it, s);

    block.clear();
    for (auto b = below == kNone ? status.begin() : std::next(handle[below]); b != above_it; ++b) {
      block.push_back(*b);
    }
    if (auto v = check.after_event(q, block)) return v;

    const std::size_t above = above_it == status.end() ? kNone : *above_it;
    if (auto v = check_new_neighbours(below, block, above, check)) return v;
  }
  return std::nullopt;
}

}  // namespace edgeland::detail
