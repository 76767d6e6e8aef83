// Stage 1 of triangulate(): de Berg et al., Computational Geometry, ch. 3.2, MakeMonotone.
//
// The sweep meets the vertices in sweeps_before order. The status holds the edges that cross
// the sweep line with the polygon's interior to their right (east): the edges running downward,
// v_i -> v_(i+1). Each has a helper, the last vertex met whose horizontal connection to the edge
// lies inside the polygon. Split vertices (both neighbours later, interior angle above 180
// degrees) connect up to the helper of the edge on their left; merge vertices (both neighbours
// earlier, reflex) are connected down from the next vertex that replaces them as a helper. A
// straight vertex has one neighbour on each side in the sweep order, so it is always regular.
#include "monotone_partition.hpp"

#include <algorithm>
#include <set>

#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "node_arena.hpp"
#include "sweep_order.hpp"

namespace edgeland::detail {
namespace {

enum class VertexKind : std::uint8_t { kStart, kSplit, kEnd, kMerge, kLeftChain, kRightChain };

std::uint32_t next_index(std::uint32_t i, std::uint32_t n) { return i + 1 == n ? 0 : i + 1; }
std::uint32_t prev_index(std::uint32_t i, std::uint32_t n) { return i == 0 ? n - 1 : i - 1; }

// de Berg's five vertex types; a regular vertex is on a left chain (interior to its east) when
// its predecessor comes first.
VertexKind classify(const Polygon& p, std::uint32_t i) {
  const auto n = static_cast<std::uint32_t>(p.size());
  const Point64 prev = p[prev_index(i, n)], v = p[i], next = p[next_index(i, n)];
  const bool prev_later = sweeps_before(v, prev), next_later = sweeps_before(v, next);
  const bool convex = orientation(prev, v, next) == Orientation::kCounterClockwise;
  if (prev_later && next_later) return convex ? VertexKind::kStart : VertexKind::kSplit;
  if (!prev_later && !next_later) return convex ? VertexKind::kEnd : VertexKind::kMerge;
  return prev_later ? VertexKind::kRightChain : VertexKind::kLeftChain;
}

// Orders the status's edges (edge i runs down from vertex i to vertex i + 1) from west to east,
// and places a vertex among them. Edges in the status never cross and never share an end, so
// their order is fixed while they are in it; std::set only compares an edge being inserted, or a
// vertex, with edges already in: the later of two upper ends is the new edge's, and it lies
// strictly inside the span of the older edge in the sweep order and strictly off its line (the
// polygon is strictly simple), so one orientation decides.
struct WestToEast {
  using is_transparent = void;
  const Polygon* polygon;

  Point64 upper(std::uint32_t e) const { return (*polygon)[e]; }
  Point64 lower(std::uint32_t e) const {
    return (*polygon)[next_index(e, static_cast<std::uint32_t>(polygon->size()))];
  }
  // East of a downward edge is to the left of its direction.
  bool east_of(Point64 v, std::uint32_t e) const {
    return orientation(upper(e), lower(e), v) == Orientation::kCounterClockwise;
  }
  bool west_of(Point64 v, std::uint32_t e) const {
    return orientation(upper(e), lower(e), v) == Orientation::kClockwise;
  }
  bool operator()(std::uint32_t a, std::uint32_t b) const {
    if (a == b) return false;
    if (sweeps_before(upper(b), upper(a))) return west_of(upper(a), b);
    return east_of(upper(b), a);
  }
  bool operator()(std::uint32_t e, Point64 v) const { return east_of(v, e); }
  bool operator()(Point64 v, std::uint32_t e) const { return west_of(v, e); }
};

class MonotoneSweep {
 public:
  explicit MonotoneSweep(const Polygon& polygon)
      : p_(polygon),
        n_(static_cast<std::uint32_t>(polygon.size())),
        status_(WestToEast{&polygon}, ArenaAllocator<std::uint32_t>(&arena_)) {
    kind_.resize(n_);
    helper_.resize(n_);
    where_.assign(n_, status_.end());
    for (std::uint32_t i = 0; i < n_; ++i) kind_[i] = classify(p_, i);
  }

  void handle(std::uint32_t i) {
    switch (kind_[i]) {
      case VertexKind::kStart:
        insert_edge(i);
        break;
      case VertexKind::kSplit:
        split(i);
        break;
      case VertexKind::kEnd:
        close_edge(prev_index(i, n_), i);
        break;
      case VertexKind::kMerge:
        close_edge(prev_index(i, n_), i);
        become_left_helper(i);
        break;
      case VertexKind::kLeftChain:
        close_edge(prev_index(i, n_), i);
        insert_edge(i);
        break;
      case VertexKind::kRightChain:
        become_left_helper(i);
        break;
    }
  }

  std::vector<Diagonal> take() { return std::move(diagonals_); }

 private:
  void insert_edge(std::uint32_t e) {
    helper_[e] = e;  // the edge's upper vertex
    where_[e] = status_.insert(e).first;
  }

  // The edge ending at vertex i leaves the status; a merge vertex helping it is connected to i.
  void close_edge(std::uint32_t e, std::uint32_t i) {
    connect_if_merge(e, i);
    EDGELAND_ASSERT(where_[e] != status_.end(), "triangulate",
                    "an edge ends before the sweep inserted it");
    status_.erase(where_[e]);
    where_[e] = status_.end();
  }

  // A split vertex connects to the helper of the edge on its left, then starts its own edge.
  void split(std::uint32_t i) {
    const std::uint32_t left = edge_west_of(i);
    diagonals_.push_back({i, helper_[left]});
    helper_[left] = i;
    insert_edge(i);
  }

  // A vertex with the interior to its west becomes the helper of the edge on its left.
  void become_left_helper(std::uint32_t i) {
    const std::uint32_t left = edge_west_of(i);
    connect_if_merge(left, i);
    helper_[left] = i;
  }

  void connect_if_merge(std::uint32_t e, std::uint32_t i) {
    if (kind_[helper_[e]] == VertexKind::kMerge) diagonals_.push_back({i, helper_[e]});
  }

  // The status edge directly west of vertex i (there is one: i has interior to its west).
  std::uint32_t edge_west_of(std::uint32_t i) const {
    auto it = status_.lower_bound(p_[i]);
    EDGELAND_ASSERT(it != status_.begin(), "triangulate", "no edge west of a vertex");
    return *std::prev(it);
  }

  // The status set's nodes from an arena, the arrays from the thread's spare storage
  // (scratch.hpp): a landscape polygon's sweep allocates nothing once the thread is warm.
  using Status = std::set<std::uint32_t, WestToEast, ArenaAllocator<std::uint32_t>>;
  const Polygon& p_;
  const std::uint32_t n_;
  NodeArena arena_;
  Status status_;
  ScratchVector<VertexKind> kind_;
  ScratchVector<std::uint32_t> helper_;  // per status edge
  ScratchVector<Status::iterator> where_;
  std::vector<Diagonal> diagonals_;
};

ScratchVector<std::uint32_t> sweep_order(const Polygon& p) {
  ScratchVector<std::uint32_t> order;
  order.resize(p.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return sweeps_before(p[a], p[b]); });
  return order;
}

}  // namespace

std::vector<Diagonal> monotone_diagonals(const Polygon& polygon) {
  MonotoneSweep sweep(polygon);
  for (const std::uint32_t i : sweep_order(polygon)) sweep.handle(i);
  return sweep.take();
}

}  // namespace edgeland::detail
