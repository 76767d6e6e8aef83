// The run sweep of validate_monotone_runs.hpp.
//
// Why it decides validity (every edge pair that may meet is looked at):
//   * Two edges of one run never meet unless they are neighbours: along a run that never
//     turns back in x nor in y, sx * x + sy * y grows strictly from vertex to vertex, so the
//     boxes of two edges with an edge between them share no point.
//   * Edges of two runs that meet do so inside both run boxes, so inside their intersection
//     I; the sweep pairs every two runs whose (closed) boxes meet, and along a monotone run
//     the edges whose boxes can meet I are one contiguous stretch, found by binary search.
//   * If no two edges of one ring meet except ring neighbours at their common vertex (a
//     spike, the only other way for neighbours to meet, is a local rule), each ring is
//     strictly simple, and with positive area counter-clockwise.
//   * If, besides, no two edges of different rings meet, every two rings are disjoint or one
//     lies inside the other (Jordan), and then its box inside the other's box: one
//     point-in-polygon test per such pair of boxes settles nesting.
// Edges of different rings that touch without crossing are allowed but need the winding
// walk of the vertex sweep (validate_one_sweep.cpp): the answer is then kUndecided.
#include "validate_monotone_runs.hpp"

#include <algorithm>
#include <vector>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "validate_event_sort.hpp"
#include "validate_exact.hpp"

namespace edgeland::detail {
namespace {

struct Box {
  Point64 low, high;
};

bool boxes_meet(const Box& a, const Box& b) noexcept {
  return a.low.x <= b.high.x && b.low.x <= a.high.x && a.low.y <= b.high.y &&
         b.low.y <= a.high.y;
}

bool box_inside(const Box& inner, const Box& outer) noexcept {
  return outer.low.x <= inner.low.x && inner.high.x <= outer.high.x &&
         outer.low.y <= inner.low.y && inner.high.y <= outer.high.y;
}

// Edges first .. first + count - 1 of one ring, monotone: x never moves against sx nor y
// against sy (a sign of 0, a coordinate constant along the run, reads as +1).
struct Run {
  Box box;  // of its two end vertices
  std::uint32_t ring;
  std::uint32_t first;
  std::uint32_t count;
  std::int8_t sx;
  std::int8_t sy;
};

struct RingView {
  const Point64* vertex;
  std::uint32_t size;
  Box box;
};

// Whether two closed segments share a point, and whether they cross at a point interior to
// both (the same test as the vertex sweep's, on unordered ends).
struct Contact {
  bool any;
  bool crossing;
};

Contact contact(Point64 a0, Point64 a1, Point64 b0, Point64 b1) noexcept {
  if (std::max(a0.x, a1.x) < std::min(b0.x, b1.x) || std::max(b0.x, b1.x) < std::min(a0.x, a1.x) ||
      std::max(a0.y, a1.y) < std::min(b0.y, b1.y) || std::max(b0.y, b1.y) < std::min(a0.y, a1.y)) {
    return {false, false};
  }
  const int o1 = orient_sign(a0, a1, b0), o2 = orient_sign(a0, a1, b1);
  if (o1 * o2 > 0) return {false, false};
  const int o3 = orient_sign(b0, b1, a0), o4 = orient_sign(b0, b1, a1);
  if (o3 * o4 > 0) return {false, false};
  if (o1 == 0 && o2 == 0) {  // collinear: on one line, lexicographic order is order along it
    return {std::max(std::min(a0, a1), std::min(b0, b1)) <= std::min(std::max(a0, a1), std::max(b0, b1)),
            false};
  }
  return {true, o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0};
}

// The local rules of one ring (>= 3 vertices, in range, no repeated vertex, no spike,
// positive area) in one pass, which with kCut also cuts the ring into runs of at most `cap`
// edges, appended to `runs` while it holds fewer than `most_runs` (so past that the runs are
// incomplete, and the caller knows from the size). Returns whether the rules hold, and then
// `view` holds the ring's box.
template <bool kCut>
bool scan_ring(const Ring& ring, std::uint32_t id, std::uint32_t cap, std::size_t most_runs,
               std::vector<Run>& runs, RingView& view) {
  const std::size_t n = ring.size();
  if (n < 3 || n >= UINT32_MAX || !in_range(ring[n - 1])) return false;
  Int128 twice_area = 0;
  Point64 prev = ring[n - 1];
  Box box{prev, prev};
  // The open run: edges first .. i - 1, from `start`, direction so far (sx, sy).
  std::uint32_t first = 0, count = 0;
  int sx = 0, sy = 0;
  Point64 start = ring[0];
  const auto close_run = [&](Point64 end) {
    if (runs.size() >= most_runs) return;
    runs.push_back({{{std::min(start.x, end.x), std::min(start.y, end.y)},
                     {std::max(start.x, end.x), std::max(start.y, end.y)}},
                    id, first, count, static_cast<std::int8_t>(sx), static_cast<std::int8_t>(sy)});
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 at = ring[i], next = ring[i + 1 == n ? 0 : i + 1];
    if (!in_range(next) || at == next) return false;
    const std::int64_t ux = coord_diff(prev.x, at.x), uy = coord_diff(prev.y, at.y);
    const std::int64_t vx = coord_diff(next.x, at.x), vy = coord_diff(next.y, at.y);
    // A spike: both neighbours on one ray from the vertex.
    if (cross_sign(ux, uy, vx, vy) == 0 && Int128(ux) * vx + Int128(uy) * vy > 0) return false;
    // Shoelace: each term has two products below 2^62 (fits int64); the sum fits Int128.
    const std::int64_t term = arith::sub<std::int64_t>(arith::mul<std::int64_t>(at.x, next.y),
                                                       arith::mul<std::int64_t>(next.x, at.y));
    twice_area = arith::add<Int128>(twice_area, term);
    box = {{std::min(box.low.x, at.x), std::min(box.low.y, at.y)},
           {std::max(box.high.x, at.x), std::max(box.high.y, at.y)}};
    if constexpr (kCut) {
      const int ex = (vx > 0) - (vx < 0), ey = (vy > 0) - (vy < 0);
      if (count == cap || ex * sx < 0 || ey * sy < 0) {  // edge i turns back: a new run
        close_run(at);
        first = static_cast<std::uint32_t>(i);
        count = 0;
        sx = sy = 0;
        start = at;
      }
      if (sx == 0) sx = ex;
      if (sy == 0) sy = ey;
      ++count;
    }
    prev = at;
  }
  if constexpr (kCut) close_run(ring[0]);
  view = {ring.data(), static_cast<std::uint32_t>(n), box};
  return twice_area > 0;
}

class RunSweep {
 public:
  RunSweep(std::span<const Polygon> polygons, std::span<const std::size_t> members,
           const RunSweepOptions& options)
      : polygons_(polygons), members_(members), options_(options) {}

  RunVerdict run() {
    std::size_t edges = 0;
    for (std::size_t r = 0; r < ring_count(); ++r) edges += ring(r).size();
    // Rings too small for long runs (a ring has at least two runs): not tried, nothing read.
    const std::size_t min_run = options_.min_edges_per_run;
    if (edges < 4 * min_run * ring_count()) return RunVerdict::kNotTried;
    if (edges >= UINT32_MAX || ring_count() >= UINT32_MAX) return RunVerdict::kNotTried;
    // More runs than this: too short on average, and the vertex sweep gets the input.
    const std::size_t most_runs = min_run == 0 ? edges : edges / min_run;
    runs_.reserve(most_runs);
    rings_.resize(ring_count());
    for (std::size_t r = 0; r < ring_count(); ++r) {
      if (!scan_ring<true>(ring(r), static_cast<std::uint32_t>(r), std::max(options_.run_cap, 1u),
                           most_runs, runs_, rings_[r])) {
        return RunVerdict::kInvalid;
      }
    }
    if (runs_.size() >= most_runs && min_run > 0) return RunVerdict::kUndecided;
    budget_ = std::size_t{options_.work_per_edge} * edges + 64;
    if (const RunVerdict v = sweep_runs(); v != RunVerdict::kValid) return v;
    return ring_count() >= 2 ? find_nesting() : RunVerdict::kValid;
  }

 private:
  // The sweep over run boxes by left side: every two runs whose boxes meet are paired once.
  RunVerdict sweep_runs() {
    const std::vector<Run> runs = sorted_by_left(runs_, [](const Run& r) { return r.box; });
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const Run& a = runs[i];
      for (std::size_t j = i + 1; j < runs.size() && runs[j].box.low.x <= a.box.high.x; ++j) {
        if (++work_ > budget_) return RunVerdict::kUndecided;
        if (!boxes_meet(a.box, runs[j].box)) continue;
        if (const RunVerdict v = check_pair(a, runs[j]); v != RunVerdict::kValid) return v;
      }
    }
    return RunVerdict::kValid;
  }

  // No two edges of different rings meet: a ring inside another is the only overlap left,
  // and then its box lies inside the other's.
  RunVerdict find_nesting() {
    std::vector<std::uint32_t> ids(rings_.size());
    for (std::uint32_t r = 0; r < ids.size(); ++r) ids[r] = r;
    ids = sorted_by_left(ids, [&](std::uint32_t r) { return rings_[r].box; });
    const auto nested = [&](std::uint32_t inner, std::uint32_t outer) {
      if (!box_inside(rings_[inner].box, rings_[outer].box)) return false;
      work_ += rings_[outer].size;
      // No edges meet, so the vertex is off the other boundary: inside or outside.
      return locate(rings_[inner].vertex[0], ring(outer)) != PointLocation::kOutside;
    };
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const Box& a = rings_[ids[i]].box;
      for (std::size_t j = i + 1; j < ids.size() && rings_[ids[j]].box.low.x <= a.high.x; ++j) {
        if (++work_ > budget_) return RunVerdict::kUndecided;
        if (!boxes_meet(a, rings_[ids[j]].box)) continue;
        if (nested(ids[j], ids[i]) || nested(ids[i], ids[j])) return RunVerdict::kInvalid;
        if (work_ > budget_) return RunVerdict::kUndecided;
      }
    }
    return RunVerdict::kValid;
  }

  // `items` ordered by the left side of box_of(item), stably.
  template <class T, class BoxOf>
  static std::vector<T> sorted_by_left(const std::vector<T>& items, BoxOf box_of) {
    std::vector<T> out;
    out.reserve(items.size());
    if (items.empty()) return out;
    std::int64_t low = box_of(items[0]).low.x, high = low;
    for (const T& item : items) {
      low = std::min(low, box_of(item).low.x);
      high = std::max(high, box_of(item).low.x);
    }
    std::vector<KeyedVertex> keys(items.size()), scratch;
    for (std::size_t k = 0; k < items.size(); ++k) {
      keys[k] = {static_cast<std::uint64_t>(box_of(items[k]).low.x - low),
                 static_cast<std::uint32_t>(k)};
    }
    sort_by_key(keys, scratch, sweep_key_bits(high - low));
    for (const KeyedVertex& k : keys) out.push_back(items[k.vertex]);
    return out;
  }

  // Vertex k (0 .. count) of a run.
  Point64 vertex(const Run& r, std::uint32_t k) const noexcept {
    const RingView& g = rings_[r.ring];
    const std::uint32_t i = r.first + k;
    return g.vertex[i == g.size ? 0 : i];
  }

  // The edges [lo, hi) of run r that may meet the box `in` (a sub-box of r's box): the edges
  // before lo end short of it, those from hi on start past it, in the run's direction.
  struct Stretch {
    std::uint32_t lo, hi;
  };
  Stretch edges_near(const Run& r, const Box& in) const noexcept {
    const auto ends_short = [&](std::uint32_t k) {
      const Point64 p = vertex(r, k + 1);
      return (r.sx >= 0 ? p.x < in.low.x : p.x > in.high.x) ||
             (r.sy >= 0 ? p.y < in.low.y : p.y > in.high.y);
    };
    const auto starts_past = [&](std::uint32_t k) {
      const Point64 p = vertex(r, k);
      return (r.sx >= 0 ? p.x > in.high.x : p.x < in.low.x) ||
             (r.sy >= 0 ? p.y > in.high.y : p.y < in.low.y);
    };
    std::uint32_t lo = 0, hi = r.count;
    while (lo < hi) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (ends_short(mid)) lo = mid + 1; else hi = mid;
    }
    const std::uint32_t first = lo;
    hi = r.count;
    while (lo < hi) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (starts_past(mid)) hi = mid; else lo = mid + 1;
    }
    return {first, lo};
  }

  // The edges of two runs whose boxes meet: kValid when none meet as they must not.
  RunVerdict check_pair(const Run& a, const Run& b) {
    const bool same_ring = a.ring == b.ring;
    const std::uint32_t n = rings_[a.ring].size;
    if (same_ring && n <= 3) return RunVerdict::kValid;  // every two edges are neighbours
    const Box in{{std::max(a.box.low.x, b.box.low.x), std::max(a.box.low.y, b.box.low.y)},
                 {std::min(a.box.high.x, b.box.high.x), std::min(a.box.high.y, b.box.high.y)}};
    const Stretch sa = edges_near(a, in), sb = edges_near(b, in);
    work_ += std::size_t{sa.hi - sa.lo} * (sb.hi - sb.lo);
    if (work_ > budget_) return RunVerdict::kUndecided;
    for (std::uint32_t i = sa.lo; i < sa.hi; ++i) {
      const Point64 a0 = vertex(a, i), a1 = vertex(a, i + 1);
      const std::uint32_t ea = a.first + i;
      for (std::uint32_t j = sb.lo; j < sb.hi; ++j) {
        const std::uint32_t eb = b.first + j;
        if (same_ring) {
          const std::uint32_t d = ea > eb ? ea - eb : eb - ea;
          if (d == 1 || d == n - 1) continue;  // ring neighbours: local rules judged them
        }
        const Contact c = contact(a0, a1, vertex(b, j), vertex(b, j + 1));
        if (!c.any) continue;
        if (same_ring || c.crossing) return RunVerdict::kInvalid;
        return RunVerdict::kUndecided;  // a touch between rings: the winding walk decides
      }
    }
    return RunVerdict::kValid;
  }

  // The rings swept: polygons_[members_[r]] for r < members_.size(), or all of polygons_.
  std::size_t ring_count() const noexcept {
    return members_.empty() ? polygons_.size() : members_.size();
  }
  const Polygon& ring(std::size_t r) const noexcept {
    return polygons_[members_.empty() ? r : members_[r]];
  }

  std::span<const Polygon> polygons_;
  std::span<const std::size_t> members_;
  RunSweepOptions options_;
  std::vector<RingView> rings_;
  std::vector<Run> runs_;
  std::size_t work_ = 0;    // box and edge tests so far
  std::size_t budget_ = 0;  // undecided past this many
};

}  // namespace

RunVerdict sweep_monotone_runs(std::span<const Polygon> polygons,
                               std::span<const std::size_t> members,
                               const RunSweepOptions& options) {
  return RunSweep(polygons, members, options).run();
}

bool local_rules_hold(const Ring& ring) {
  std::vector<Run> no_runs;
  RingView view{};
  return scan_ring<false>(ring, 0, 1, 0, no_runs, view);
}

}  // namespace edgeland::detail
