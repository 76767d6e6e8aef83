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
// walk of the vertex sweep (validate_accept_sweep.cpp): the answer is then kUndecided.
#include "validate_monotone_runs.hpp"

#include <algorithm>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "validate_event_sort.hpp"
#include "validate_exact.hpp"
#include "validate_selection.hpp"

namespace edgeland::detail {
namespace {

// Edges first .. first + count - 1 of one ring, monotone: x never moves against sx (+1 or -1)
// nor y against sy.
struct Run {
  Box64 box;  // of its two end vertices
  std::uint32_t ring;
  std::uint32_t first;
  std::uint32_t count;
  std::int8_t sx;
  std::int8_t sy;
};

struct RingView {
  const Point64* vertex;
  std::uint32_t size;
  Box64 box;
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
    return {std::max(std::min(a0, a1), std::min(b0, b1)) <=
                std::min(std::max(a0, a1), std::max(b0, b1)),
            false};
  }
  return {true, o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0};
}

// Where a ring's runs start: a ring-local edge number per run, kept in a buffer of fixed
// size. Writes past the end all go to its last slot, so the loop that cuts needs no branch;
// `count` says how many runs were cut (more than fit when count >= size).
struct RunStarts {
  std::uint32_t* slot;
  std::size_t size;  // >= 1
  std::size_t count = 0;
};

// The local rules of one ring (>= 3 vertices, in range, no repeated vertex, no spike,
// positive area) in one pass, which with kCut also cuts the ring into runs of at most `cap`
// edges (recorded in `starts`). Returns whether the rules hold.
//
// A spike can only sit where a run is cut: the edge after it runs exactly against the edge
// before it, so it turns back in x or in y. Inside a run the test is skipped. The loop keeps
// little state (this pass is most of the cost on smooth input): no box, no previous vertex.
template <bool kCut>
bool scan_ring(const Ring& ring, std::uint32_t cap, RunStarts& starts) {
  const std::size_t n = ring.size();
  if (n < 3 || n >= UINT32_MAX || !in_range(ring[n - 1])) return false;
  const Point64* const v = ring.data();
  Int128 twice_area = 0;
  // The last nonzero sign of the edges' x and y steps so far, and the edges left until the
  // next cut forced by the cap (cuts every `cap` edges, whatever other cuts fall between,
  // so no run is longer; nothing in this loop waits on the previous cut).
  int lx = 0, ly = 0;
  std::uint32_t to_cap = 0;
  // Kept in registers here (through `starts` every write would wait for the last).
  std::uint32_t* const slot = starts.slot;
  const std::size_t last_slot = starts.size - 1;
  std::size_t cuts = starts.count;
  // Edge i, from v[i] to `next`: whether the rules hold at v[i].
  const auto edge = [&](std::size_t i, Point64 next) {
    const Point64 at = v[i];
    if (!in_range(next) || at == next) return false;
    const std::int64_t vx = coord_diff(next.x, at.x), vy = coord_diff(next.y, at.y);
    bool check_spike = true;
    if constexpr (kCut) {
      // A run ends before an edge turning back against an earlier edge of the run: with
      // lx, ly taken over the edges before the run too, a run's nonzero x steps all have
      // one sign, and so do its y steps.
      const int ex = (vx > 0) - (vx < 0), ey = (vy > 0) - (vy < 0);
      const bool cut = (to_cap == 0) | (ex * lx < 0) | (ey * ly < 0);
      slot[std::min(cuts, last_slot)] = static_cast<std::uint32_t>(i);
      cuts += cut;
      lx = ex != 0 ? ex : lx;
      ly = ey != 0 ? ey : ly;
      to_cap = to_cap == 0 ? cap - 1 : to_cap - 1;
      check_spike = cut;
    }
    if (check_spike) {  // both neighbours on one ray from the vertex
      const Point64 prev = v[i == 0 ? n - 1 : i - 1];
      const std::int64_t ux = coord_diff(prev.x, at.x), uy = coord_diff(prev.y, at.y);
      if (cross_sign(ux, uy, vx, vy) == 0 && Int128(ux) * vx + Int128(uy) * vy > 0) return false;
    }
    // Shoelace: each term has two products below 2^62 (fits int64); the sum fits Int128.
    const std::int64_t term = arith::sub<std::int64_t>(arith::mul<std::int64_t>(at.x, next.y),
                                                       arith::mul<std::int64_t>(next.x, at.y));
    twice_area = arith::add<Int128>(twice_area, term);
    return true;
  };
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (!edge(i, v[i + 1])) return false;
  }
  if (!edge(n - 1, v[0])) return false;
  starts.count = cuts;
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
    // More runs than this: too short on average, and the vertex sweep gets the input. A set
    // of several rings must promise twice as much: its rings may touch (pieces of one
    // clipped landscape often share edges), and then the work here was for nothing.
    const std::size_t per_run = ring_count() >= 2 ? 2 * min_run : min_run;
    const std::size_t most_runs = per_run == 0 ? edges : edges / per_run;
    ScratchVector<std::uint32_t> starts;
    starts.resize(most_runs + 1);
    RunStarts cut{starts.data(), starts.size()};
    rings_.resize(ring_count());
    ScratchVector<std::size_t> first_run;
    first_run.resize(ring_count() + 1);
    const std::uint32_t cap = std::max(options_.run_cap, 1u);
    for (std::size_t r = 0; r < ring_count(); ++r) {
      first_run[r] = cut.count;
      if (!scan_ring<true>(ring(r), cap, cut)) return RunVerdict::kInvalid;
      rings_[r].vertex = ring(r).data();
      rings_[r].size = static_cast<std::uint32_t>(ring(r).size());
    }
    if (cut.count > most_runs) return RunVerdict::kUndecided;
    first_run[ring_count()] = cut.count;
    runs_.reserve(cut.count);
    for (std::size_t r = 0; r < ring_count(); ++r) {
      for (std::size_t k = first_run[r]; k < first_run[r + 1]; ++k) {
        const std::uint32_t end = k + 1 < first_run[r + 1] ? starts[k + 1] : rings_[r].size;
        add_run(static_cast<std::uint32_t>(r), starts[k], end - starts[k]);
      }
      // The ring's box: that of its runs' boxes.
      Box64& box = rings_[r].box;
      box = runs_[first_run[r]].box;
      for (std::size_t k = first_run[r] + 1; k < first_run[r + 1]; ++k) box.expand(runs_[k].box);
    }
    budget_ = std::size_t{options_.work_per_edge} * edges + 64;
    if (const RunVerdict v = sweep_runs(); v != RunVerdict::kValid) return v;
    return ring_count() >= 2 ? find_nesting() : RunVerdict::kValid;
  }

 private:
  // Edges first .. first + count - 1 of ring r, a monotone run.
  void add_run(std::uint32_t r, std::uint32_t first, std::uint32_t count) {
    Run run{{}, r, first, count, 0, 0};
    const Point64 a = vertex(run, 0), b = vertex(run, count);
    run.box = segment_box(a, b);
    // Along the run each coordinate only grows or only shrinks (or stays): its ends tell how.
    run.sx = a.x <= b.x ? 1 : -1;
    run.sy = a.y <= b.y ? 1 : -1;
    runs_.push_back(run);
  }

  // The sweep over run boxes by left side: every two runs whose boxes meet are paired once.
  RunVerdict sweep_runs() {
    const std::vector<Run> runs = sorted_by_left(runs_, [](const Run& r) { return r.box; });
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const Run& a = runs[i];
      for (std::size_t j = i + 1; j < runs.size() && runs[j].box.min.x <= a.box.max.x; ++j) {
        if (++work_ > budget_) return RunVerdict::kUndecided;
        if (!a.box.overlaps(runs[j].box)) continue;
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
      if (!rings_[outer].box.contains(rings_[inner].box)) return false;
      work_ += rings_[outer].size;
      // No edges meet, so the vertex is off the other boundary: inside or outside.
      return locate(rings_[inner].vertex[0], ring(outer)) != PointLocation::kOutside;
    };
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const Box64& a = rings_[ids[i]].box;
      for (std::size_t j = i + 1; j < ids.size() && rings_[ids[j]].box.min.x <= a.max.x; ++j) {
        if (++work_ > budget_) return RunVerdict::kUndecided;
        if (!a.overlaps(rings_[ids[j]].box)) continue;
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
    std::int64_t low = box_of(items[0]).min.x, high = low;
    for (const T& item : items) {
      low = std::min(low, box_of(item).min.x);
      high = std::max(high, box_of(item).min.x);
    }
    std::vector<KeyedVertex> keys(items.size()), scratch;
    for (std::size_t k = 0; k < items.size(); ++k) {
      keys[k] = {static_cast<std::uint64_t>(box_of(items[k]).min.x - low),
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
  Stretch edges_near(const Run& r, const Box64& in) const noexcept {
    const auto ends_short = [&](std::uint32_t k) {
      const Point64 p = vertex(r, k + 1);
      return (r.sx >= 0 ? p.x < in.min.x : p.x > in.max.x) ||
             (r.sy >= 0 ? p.y < in.min.y : p.y > in.max.y);
    };
    const auto starts_past = [&](std::uint32_t k) {
      const Point64 p = vertex(r, k);
      return (r.sx >= 0 ? p.x > in.max.x : p.x < in.min.x) ||
             (r.sy >= 0 ? p.y > in.max.y : p.y < in.min.y);
    };
    std::uint32_t lo = 0, hi = r.count;
    while (lo < hi) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (ends_short(mid))
        lo = mid + 1;
      else
        hi = mid;
    }
    const std::uint32_t first = lo;
    hi = r.count;
    while (lo < hi) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (starts_past(mid))
        hi = mid;
      else
        lo = mid + 1;
    }
    return {first, lo};
  }

  // The edges of two runs whose boxes meet: kValid when none meet as they must not.
  RunVerdict check_pair(const Run& a, const Run& b) {
    const bool same_ring = a.ring == b.ring;
    const std::uint32_t n = rings_[a.ring].size;
    if (same_ring && n <= 3) return RunVerdict::kValid;  // every two edges are neighbours
    const Box64 in{{std::max(a.box.min.x, b.box.min.x), std::max(a.box.min.y, b.box.min.y)},
                   {std::min(a.box.max.x, b.box.max.x), std::min(a.box.max.y, b.box.max.y)}};
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

  std::size_t ring_count() const noexcept { return selected_count(polygons_, members_); }
  const Polygon& ring(std::size_t r) const noexcept {
    return selected_ring(polygons_, members_, r);
  }

  std::span<const Polygon> polygons_;
  std::span<const std::size_t> members_;
  RunSweepOptions options_;
  ScratchVector<RingView> rings_;
  ScratchVector<Run> runs_;
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
  std::uint32_t unused = 0;
  RunStarts no_runs{&unused, 1};
  return scan_ring<false>(ring, 1, no_runs);
}

}  // namespace edgeland::detail
