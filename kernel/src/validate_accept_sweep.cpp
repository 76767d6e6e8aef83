// The fast acceptance path of validate() (validate_checks.hpp): the local rules of every ring
// in O(n) and the sweep over monotone runs (validate_monotone_runs.hpp), which settle most
// smooth inputs; then, for what they leave undecided, ONE sweep over the edges of all rings
// together that checks strict simplicity and disjoint interiors at once. Events are vertices
// sorted by 64-bit keys (validate_event_sort.hpp); the status is a sorted array of edge
// numbers, cut into blocks when it grows wide (validate_status.hpp).
//
// Its signs are exact in int64 when the input's box is narrow (validate_exact.hpp), so the sweep
// is compiled twice, for int64 and for Int128 signs, and the box picks one. Its arrays come
// from per-thread spares (edgeland/kernel/scratch.hpp): small inputs are validated on every clip.
//
// It only ever concludes "valid". At the first sign of trouble it gives up, and validate()
// runs the reporting checks, which say exactly what is wrong; so reports never depend on it.
//
// Why one sweep suffices: it is the sweep of validate_report_sweep.hpp over all edges, asking at
// each event point q and of each new pair of status neighbours the union of the questions of the
// two reporting checks (validate_self_intersection.cpp, validate_overlap.cpp):
//   * two edges of one ring that are not ring neighbours must share no point: at q, every edge
//     containing q is listed, so touching and collinear overlap are seen at an event; a
//     crossing is a crossing of the whole arrangement;
//   * two edges of different rings must not cross, and edges through q in different
//     directions cross at q;
//   * the winding walk of validate_overlap.cpp around q must never count 2.
// If no two edges cross, the status order is consistent and the Shamos-Hoey argument of
// validate_report_sweep.hpp applies to the whole arrangement: the leftmost crossing, if any, is
// seen at an event or between new status neighbours. Without crossings, the rings are strictly
// simple (nothing else can make two edges of one ring meet), counter-clockwise (checked
// locally), and the winding walk is exact.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "validate_checks.hpp"
#include "validate_event_sort.hpp"
#include "validate_exact.hpp"
#include "validate_monotone_runs.hpp"
#include "validate_selection.hpp"
#include "validate_status.hpp"

namespace edgeland::detail {
namespace {

// The status (validate_status.hpp) costs O(kBlock + width / kBlock) per insert: bounded while
// the width stays below this limit. Past it the sweep gives up and the reporting sweep, a
// balanced tree, decides; so the path is O(n log n) for any input.
constexpr std::size_t kStatusLimit = std::size_t{1} << 18;
// Above this many edges starting at one point, order_run sorts instead of inserting.
constexpr std::size_t kInsertionLimit = 16;

struct Edge {
  Point64 left;   // lexicographically smaller end
  Point64 right;  // larger end
  // right - left, formed once: every sign the sweep asks of an edge starts from it.
  std::int64_t dx, dy;
  std::uint32_t ring;
  bool forward;  // the ring runs from left to right
};

struct RingRange {
  std::uint32_t begin;  // first edge (= first vertex) of the ring in the global numbering
  std::uint32_t size;
};

using Event = KeyedVertex;

bool is_vertical(const Edge& e) noexcept { return e.dx == 0; }

// The signs the sweep asks of edges, in int64 when the input's box is narrow (kNarrow,
// validate_exact.hpp), else through Int128.
template <bool kNarrow>
struct EdgeSigns {
  // Sign of orient(e.left, e.right, p): +1 when p is left of the edge.
  static int orient(const Edge& e, Point64 p) noexcept {
    return cross_sign_in<kNarrow>(e.dx, e.dy, coord_diff(p.x, e.left.x), coord_diff(p.y, e.left.y));
  }

  // -1 when the status edge t passes strictly below q, 0 through q, +1 above
  // (validate_report_sweep.hpp).
  static int side_of_point(const Edge& t, Point64 q) noexcept {
    if (is_vertical(t)) return 0;
    return -orient(t, q);
  }

  // Order of the directions of two edges leaving one point rightward (upward if vertical).
  static int compare_directions(const Edge& a, const Edge& b) noexcept {
    const bool av = is_vertical(a), bv = is_vertical(b);
    if (av || bv) return av == bv ? 0 : (av ? 1 : -1);
    return -cross_sign_in<kNarrow>(a.dx, a.dy, b.dx, b.dy);
  }

  // Whether two closed segments share a point (any contact) and whether they cross at a
  // point interior to both.
  struct Contact {
    bool any;
    bool crossing;
  };

  static Contact contact(const Edge& a, const Edge& b) noexcept {
    // Disjoint boxes: no contact. Status neighbours overlap in x, so y decides most pairs.
    if (std::max(a.left.y, a.right.y) < std::min(b.left.y, b.right.y) ||
        std::max(b.left.y, b.right.y) < std::min(a.left.y, a.right.y) || a.right.x < b.left.x ||
        b.right.x < a.left.x) {
      return {false, false};
    }
    const int o1 = orient(a, b.left), o2 = orient(a, b.right);
    if (o1 * o2 > 0) return {false, false};
    const int o3 = orient(b, a.left), o4 = orient(b, a.right);
    if (o3 * o4 > 0) return {false, false};
    if (o1 == 0 && o2 == 0) {  // collinear: on one line, lexicographic order is order along it
      // Not reached by tests: new status neighbours never lie on one line (two collinear edges
      // cut by the sweep line at q both contain q, so both sit in the run through q).
      return {std::max(a.left, b.left) <= std::min(a.right, b.right), false};
    }
    return {true, o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0};
  }
};

class OneSweep {
 public:
  OneSweep(std::span<const Polygon> polygons, std::span<const std::size_t> members,
           bool local_rules_known)
      : polygons_(polygons), members_(members), local_rules_known_(local_rules_known) {}

  bool run() {
    if (!build()) return false;
    sort_by_key(events_, events_scratch_, key_bits_);
    return narrow_ ? sweep<true>() : sweep<false>();
  }

 private:
  // The events in order, grouped by point.
  template <bool kNarrow>
  bool sweep() {
    for (std::size_t g = 0; g < events_.size();) {
      std::size_t h = g + 1;
      while (h < events_.size() && events_[h].key == events_[g].key) ++h;
      if (!(h == g + 1 ? vertex_event<kNarrow>(g) : event<kNarrow>(g, h))) return false;
      g = h;
    }
    return status_.empty();
  }

  // Flattens the rings into edges and events once each passes its local rules (unless
  // already known to).
  bool build() {
    std::size_t total = 0;
    for (std::size_t r = 0; r < ring_count(); ++r) {
      if (!local_rules_known_ && !local_rules_hold(ring(r))) return false;
      total += ring(r).size();
    }
    if (total >= UINT32_MAX || ring_count() >= UINT32_MAX) return false;
    multi_ = ring_count() >= 2;
    edges_.reserve(total);
    events_.reserve(total);
    rings_.reserve(ring_count());
    std::uint32_t id = 0;
    Box64 box{{kCoordBound, kCoordBound}, {-kCoordBound, -kCoordBound}};  // empty until expanded
    for (std::size_t r = 0; r < ring_count(); ++r) {
      const Polygon& p = ring(r);
      rings_.push_back({id, static_cast<std::uint32_t>(p.size())});
      for (std::size_t i = 0; i < p.size(); ++i, ++id) {
        const Point64 a = p[i], b = p[i + 1 == p.size() ? 0 : i + 1];
        const bool forward = a < b;
        const Point64 left = forward ? a : b, right = forward ? b : a;
        edges_.push_back({left, right, coord_diff(right.x, left.x), coord_diff(right.y, left.y),
                          static_cast<std::uint32_t>(r), forward});
        box.expand(a);
      }
    }
    // Each vertex as one key in as few bits as the box needs.
    narrow_ = narrow_box(box.min, box.max);
    const unsigned y_bits = sweep_key_bits(box.max.y - box.min.y);
    key_bits_ = y_bits + sweep_key_bits(box.max.x - box.min.x);
    for (std::uint32_t v = 0; v < total; ++v) {
      events_.push_back({sweep_key(edge_start(v), box.min, y_bits), v});
    }
    if (multi_) cover_.assign(total, 0);
    seen_.assign(ring_count(), 0);
    return true;
  }

  std::uint32_t previous_edge(std::uint32_t v) const noexcept {
    const RingRange& r = rings_[edges_[v].ring];
    return v == r.begin ? r.begin + r.size - 1 : v - 1;
  }

  // Edges of one ring that may touch: ring neighbours, or any two edges of a triangle.
  bool may_touch(std::uint32_t a, std::uint32_t b) const noexcept {
    const RingRange& r = rings_[edges_[a].ring];
    if (r.size <= 3) return true;
    const std::uint32_t d = a > b ? a - b : b - a;
    return d == 1 || d == r.size - 1;
  }

  // Index of the first status edge not below q.
  template <bool kNarrow>
  std::size_t first_not_below(Point64 q) const noexcept {
    return status_.partition_point(
        [&](std::uint32_t e) { return EdgeSigns<kNarrow>::side_of_point(edges_[e], q) < 0; });
  }

  // The common event: one vertex v alone at its point q, its two edges in and out. The same
  // steps as event() below, without lists; an edge passing through q sends it there.
  template <bool kNarrow>
  bool vertex_event(std::size_t g) {
    using Signs = EdgeSigns<kNarrow>;
    const std::uint32_t v = events_[g].vertex;
    const std::uint32_t in = previous_edge(v);
    const Edge& ein = edges_[in];
    const Edge& eout = edges_[v];
    const Point64 q = ein.forward ? ein.right : ein.left;
    const std::size_t i = first_not_below<kNarrow>(q);
    std::size_t j = i;
    while (j < status_.size() && edges_[status_[j]].right == q) ++j;
    if (j < status_.size() && Signs::side_of_point(edges_[status_[j]], q) == 0) {
      return event_at<kNarrow>(q, &events_[g], 1);  // an edge passes through q
    }
    const std::size_t ended = j - i;
    // `in` ends at q, and `out` starts there, when the ring runs rightward along them.
    const bool in_ends = ein.forward, out_starts = eout.forward;
    std::size_t k = 0;
    std::uint32_t block[2] = {0, 0};  // the edges leaving q, bottom-up
    if (in_ends == out_starts) {      // the ring passes q: one edge ends, the other starts
      if (ended != 1) return false;
      block[0] = in_ends ? v : in;
      status_.set(i, block[0]);
      k = 1;
    } else if (out_starts) {  // both edges start at q: insert them bottom-up
      if (ended != 0 || status_.size() >= kStatusLimit) return false;
      const int c = Signs::compare_directions(ein, eout);
      const bool in_first = c < 0 || (c == 0 && in < v);
      block[0] = in_first ? in : v;
      block[1] = in_first ? v : in;
      status_.replace(i, 0, block, 2);
      k = 2;
    } else {  // both end at q
      if (ended != 2) return false;
      status_.replace(i, 2, block, 0);
    }
    return neighbourhood_fine<kNarrow>(i, block, k);
  }

  // The events g..h-1 share one point q.
  template <bool kNarrow>
  bool event(std::size_t g, std::size_t h) {
    return event_at<kNarrow>(edge_start(events_[g].vertex), &events_[g], h - g);
  }

  // Sorts the two edges of each of the `count` vertices of `group` into ending_ and
  // starting_, by whether the ring runs into q along them. Both lists are written by index
  // into room kept from earlier events, each edge to both with only the right count
  // advanced: no push, no fill, no branch per edge.
  void split_edges_at(const Event* group, std::size_t count) {
    if (ending_.size() < 2 * count) {
      ending_.resize(2 * count);
      starting_.resize(2 * count);
    }
    std::uint32_t* const ends = ending_.data();
    std::uint32_t* const starts = starting_.data();
    std::size_t e = 0, s = 0;
    for (std::size_t k = 0; k < count; ++k) {
      const std::uint32_t v = group[k].vertex;
      const std::uint32_t in = previous_edge(v);
      const bool in_ends = edges_[in].forward, out_starts = edges_[v].forward;
      ends[e] = in;
      starts[s] = in;
      e += in_ends;
      s += !in_ends;
      ends[e] = v;
      starts[s] = v;
      e += !out_starts;
      s += out_starts;
    }
    ending_count_ = e;
    starting_count_ = s;
  }

  // The vertices of `count` events at q, in general.
  template <bool kNarrow>
  bool event_at(Point64 q, const Event* group, std::size_t count) {
    using Signs = EdgeSigns<kNarrow>;
    split_edges_at(group, count);
    through_.clear();

    // The status edges through q form one run [i, j), holding every edge ending at q.
    const std::size_t i = first_not_below<kNarrow>(q);
    std::size_t j = i, ended = 0;
    for (; j < status_.size(); ++j) {
      const std::uint32_t e = status_[j];
      if (edges_[e].right == q) {
        ++ended;
      } else if (Signs::side_of_point(edges_[e], q) == 0) {
        through_.push_back(e);
      } else {
        break;
      }
    }
    // Not a consistent status: let the reporting sweep tell.
    if (ended != ending_count_) return false;

    if (!through_.empty() || count > 1) {
      // Edges through q in different directions cross there.
      for (std::size_t k = 1; k < through_.size(); ++k) {
        if (Signs::compare_directions(edges_[through_[k - 1]], edges_[through_[k]]) != 0) {
          return false;
        }
      }
      // Edges of one ring at q must be ring neighbours. The two edges of one vertex are, so
      // only a ring met twice at q (at two vertices, or at a vertex and a passing edge)
      // needs the test of every pair.
      ++stamp_;
      bool met_twice = false;
      const auto meet = [&](std::uint32_t edge) {
        std::uint32_t& seen = seen_[edges_[edge].ring];
        met_twice = met_twice || seen == stamp_;
        seen = stamp_;
      };
      for (std::size_t k = 0; k < count; ++k) meet(group[k].vertex);
      for (const std::uint32_t e : through_) meet(e);
      if (met_twice && !ring_neighbours_only()) return false;
    }

    // The new run replaces [i, j): edges through q and edges leaving q, bottom-up, i.e. by
    // direction (collinear ones by number, fixed for their life). Starting edges are sorted
    // into the through edges, already in order.
    const std::size_t passing = through_.size(), k = passing + starting_count_;
    for (std::size_t m = 0; m < starting_count_; ++m) through_.push_back(starting_[m]);
    order_run<kNarrow>(through_.data(), passing, k);
    if (k > j - i && status_.size() + (k - (j - i)) > kStatusLimit) return false;
    status_.replace(i, j - i, through_.data(), k);
    return neighbourhood_fine<kNarrow>(i, through_.data(), k);
  }

  // Sorts run[passing, k) into the ordered run[0, passing) bottom-up: by direction, collinear
  // edges by number. A few edges start at a usual vertex (insertion); many start at one point
  // only in a crowd of rings sharing a corner, where a sort and a merge keep the event
  // O(k log k) instead of O(k^2) (N identical squares once took minutes).
  template <bool kNarrow>
  void order_run(std::uint32_t* run, std::size_t passing, std::size_t k) const {
    const auto below = [&](std::uint32_t a, std::uint32_t b) {
      const int c = EdgeSigns<kNarrow>::compare_directions(edges_[a], edges_[b]);
      return c < 0 || (c == 0 && a < b);
    };
    if (k - passing > kInsertionLimit) {
      std::sort(run + passing, run + k, below);
      std::inplace_merge(run, run + passing, run + k, below);
      return;
    }
    for (std::size_t placed = passing; placed < k; ++placed) {
      const std::uint32_t s = run[placed];
      std::size_t at = placed;
      for (; at > 0 && below(s, run[at - 1]); --at) run[at] = run[at - 1];
      run[at] = s;
    }
  }

  // Whether every two edges of one ring at q (ending_, through_, starting_) are neighbours.
  // A strictly simple ring meets q at one vertex or along one edge, so more than two edges of
  // one ring fail at once; grouping by ring keeps a crowded point O(m log m).
  bool ring_neighbours_only() {
    at_.clear();
    at_.insert(at_.end(), ending_.begin(), ending_.begin() + ending_count_);
    at_.insert(at_.end(), through_.begin(), through_.end());
    at_.insert(at_.end(), starting_.begin(), starting_.begin() + starting_count_);
    std::sort(at_.begin(), at_.end(), [&](std::uint32_t a, std::uint32_t b) {
      return edges_[a].ring < edges_[b].ring || (edges_[a].ring == edges_[b].ring && a < b);
    });
    for (std::size_t a = 0; a < at_.size();) {
      std::size_t b = a + 1;
      while (b < at_.size() && edges_[at_[b]].ring == edges_[at_[a]].ring) ++b;
      if (b - a > 2 || (b - a == 2 && !may_touch(at_[a], at_[a + 1]))) return false;
      a = b;
    }
    // Not reached by tests: this runs only when a ring is met twice at q, and such a ring has
    // three or more edges there, which the loop rejects.
    return true;
  }

  // After an event, the k edges through or leaving q, `block`, sit at [i, i + k) of the
  // status: walk the winding numbers around q and test the pairs of new neighbours.
  template <bool kNarrow>
  [[gnu::always_inline]] bool neighbourhood_fine(std::size_t i, const std::uint32_t* block,
                                                 std::size_t k) {
    const std::uint32_t kNo = UINT32_MAX;
    const std::uint32_t below = i > 0 ? status_[i - 1] : kNo;
    const std::uint32_t above = i + k < status_.size() ? status_[i + k] : kNo;
    if (multi_ && !winding_stays_below_two<kNarrow>(below, block, k)) return false;
    const std::uint32_t low = k > 0 ? block[0] : above;
    const std::uint32_t high = k > 0 ? block[k - 1] : below;
    if (below != kNo && low != kNo && !neighbours_fine<kNarrow>(below, low)) return false;
    if (k > 0 && above != kNo && !neighbours_fine<kNarrow>(high, above)) return false;
    return true;
  }

  Point64 edge_start(std::uint32_t v) const noexcept {
    const Edge& e = edges_[v];
    return e.forward ? e.left : e.right;
  }

  // The winding walk of validate_overlap.cpp over the sectors right of q, counter-clockwise
  // from straight down, storing the count above each of the k edges of `block`.
  template <bool kNarrow>
  bool winding_stays_below_two(std::uint32_t below, const std::uint32_t* block, std::size_t k) {
    int cover = below == UINT32_MAX ? 0 : cover_[below];
    for (std::size_t first = 0; first < k;) {
      std::size_t last = first + 1;
      while (last < k && EdgeSigns<kNarrow>::compare_directions(edges_[block[first]],
                                                                edges_[block[last]]) == 0) {
        ++last;
      }
      int entering = 0;
      for (std::size_t m = first; m < last; ++m) {
        if (edges_[block[m]].forward) {
          ++entering;
          ++cover;
        } else {
          --cover;
        }
      }
      if (entering > 1 || cover >= 2 || cover < 0) return false;
      for (std::size_t m = first; m < last; ++m) cover_[block[m]] = static_cast<std::int8_t>(cover);
      first = last;
    }
    return true;
  }

  // New status neighbours: of one ring they must not meet unless ring neighbours; of two
  // rings they must not cross (touching is judged at events).
  template <bool kNarrow>
  bool neighbours_fine(std::uint32_t a, std::uint32_t b) const noexcept {
    using Signs = EdgeSigns<kNarrow>;
    if (edges_[a].ring == edges_[b].ring) {
      return may_touch(a, b) || !Signs::contact(edges_[a], edges_[b]).any;
    }
    return !Signs::contact(edges_[a], edges_[b]).crossing;
  }

  std::size_t ring_count() const noexcept { return selected_count(polygons_, members_); }
  const Polygon& ring(std::size_t r) const noexcept {
    return selected_ring(polygons_, members_, r);
  }

  std::span<const Polygon> polygons_;
  std::span<const std::size_t> members_;
  bool local_rules_known_;  // every ring passes local_rules_hold (the run sweep said so)
  bool multi_ = false;
  bool narrow_ = false;  // the input's box is narrow: signs in int64 (validate_exact.hpp)
  // Edge v runs from vertex v to the next vertex of its ring.
  ScratchVector<Edge> edges_;
  ScratchVector<RingRange> rings_;
  ScratchVector<Event> events_;
  ScratchVector<Event> events_scratch_;
  unsigned key_bits_ = 0;  // every event key is below 2^key_bits_
  // Winding number just above each placed edge (sets only).
  ScratchVector<std::int8_t> cover_;
  SweepStatus status_;
  // At an event: the edges ending at q, ending_[0, ending_count_), and those starting there.
  ScratchVector<std::uint32_t> ending_;
  ScratchVector<std::uint32_t> starting_;
  std::size_t ending_count_ = 0, starting_count_ = 0;
  ScratchVector<std::uint32_t> through_;
  ScratchVector<std::uint32_t> at_;
  // Per ring: the last stamp_ of an event that met it.
  ScratchVector<std::uint32_t> seen_;
  std::uint32_t stamp_ = 0;
};

// The one place the sweeps are run: the run sweep settles smooth inputs from n / 16 sorted
// runs; what it leaves undecided (touching rings, spiky or tiny rings) gets the vertex sweep.
bool accepted_by_one_sweep_of(std::span<const Polygon> polygons,
                              std::span<const std::size_t> members) {
  switch (sweep_monotone_runs(polygons, members)) {
    case RunVerdict::kValid:
      return true;
    case RunVerdict::kInvalid:
      return false;
    case RunVerdict::kUndecided:
      return OneSweep(polygons, members, true).run();
    case RunVerdict::kNotTried:
      break;
  }
  return OneSweep(polygons, members, false).run();
}

}  // namespace

bool accepted_by_one_sweep(std::span<const Polygon> polygons) {
  return accepted_by_one_sweep_of(polygons, {});
}

bool accepted_by_one_sweep(std::span<const Polygon> polygons,
                           std::span<const std::size_t> members) {
  // OneSweep reads an empty `members` as all polygons.
  return members.empty() || accepted_by_one_sweep_of(polygons, members);
}

}  // namespace edgeland::detail
