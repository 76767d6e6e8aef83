#pragma once
// The real inputs of single pipeline stages (clip/src: noding, plane graph, labeling, assembly,
// hole splitting), built by running the stages before them as pipeline.cpp does, and the
// brute-force references the stage tests (tests/clip/*_test.cpp named after the stages) compare
// them with: lattice unit steps, the rings snap rounding made of the input rings, and winding
// numbers at points just beside a stretch. The references use the kernel's predicates and
// winding_number only, never the stage under test.
#include <rapidcheck.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "input_edges.hpp"
#include "labeling.hpp"
#include "noding.hpp"
#include "plane_graph.hpp"
#include "snap_rounding.hpp"
#include "stage_outputs.hpp"

namespace edgeland::test::stages {

// Uniform in [lo, hi] whatever RapidCheck's current size (inRange alone narrows its range with
// the size, down to lo alone at size 0); shrinks towards lo.
inline std::int64_t uniform(std::int64_t lo, std::int64_t hi) {
  return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange<std::int64_t>(lo, hi + 1));
}
inline int uniform_int(int lo, int hi) { return static_cast<int>(uniform(lo, hi)); }

// Rings of random points in [-side / 2, side / 2]^2: self-intersecting, overlapping each other,
// with repeated points (consecutive ones too), spikes folded back onto themselves (all the way or
// part way) and rings that collapse to a point or a segment. Crowded on purpose, as in
// snap_rounding_test. Small sides keep SideProbe's scaled points in range; `wide` adds sides up to
// the coordinate range (for stages that need no probe).
inline rc::Gen<std::vector<Ring>> crowded_rings(int max_rings, int max_points, bool wide = false) {
  return rc::gen::exec([=] {
    const std::int64_t side = wide ? *rc::gen::element<std::int64_t>(6, 40, 1000, 3'000'000'000)
                                   : *rc::gen::element<std::int64_t>(4, 6, 12, 40);
    auto coord = [side] { return uniform(0, side) - side / 2; };
    const int rings = uniform_int(1, max_rings);
    std::vector<Ring> out;
    for (int r = 0; r < rings; ++r) {
      const int n = uniform_int(1, max_points);
      Ring ring;
      for (int i = 0; i < n; ++i) {
        const int kind = uniform_int(0, 9);
        if (kind == 0 && !ring.empty()) {
          ring.push_back(ring.back());  // a repeated point
        } else if (kind == 1 && ring.size() >= 2) {
          ring.push_back(ring[ring.size() - 2]);  // back along the last edge: a spike
        } else if (kind == 2 && ring.size() >= 2 && ring.back() != ring[ring.size() - 2]) {
          // Back along the last edge to a lattice point inside it, if it has one.
          const Point64 p = ring[ring.size() - 2], q = ring.back();
          const std::int64_t g = std::gcd(std::abs(q.x - p.x), std::abs(q.y - p.y));
          const std::int64_t k = g > 1 ? uniform(1, g - 1) : 0;
          ring.push_back({p.x + (q.x - p.x) / g * k, p.y + (q.y - p.y) / g * k});
        } else {
          ring.push_back({coord(), coord()});
        }
      }
      out.push_back(std::move(ring));
    }
    return out;
  });
}

inline std::string str(Point64 p) {
  return "(" + std::to_string(p.x) + " " + std::to_string(p.y) + ")";
}

inline std::string str(const detail::SideState& s) {
  return "state (" + std::to_string(s.by_channel[0]) + " " + std::to_string(s.by_channel[1]) + ")";
}

// Half-edge h and its first stretch, for messages.
inline std::string str_half_edge(const detail::PlaneGraph& g, std::uint32_t h) {
  return "half-edge " + std::to_string(h) + " " + str(g.vertices[g.origin(h)]) + " -> " +
         str(g.first_step(h));
}

// Counter-clockwise order of directions from angle 0 inclusive: half-plane, then cross product.
inline bool ccw_before(Point64 d1, Point64 d2) {
  const bool lower1 = d1.y < 0 || (d1.y == 0 && d1.x < 0);
  const bool lower2 = d2.y < 0 || (d2.y == 0 && d2.x < 0);
  if (lower1 != lower2) return lower2;
  return Int128(d1.x) * d2.y - Int128(d1.y) * d2.x > 0;
}

// The lattice step of a -> b: b - a divided by the gcd of its coordinates (a != b).
inline Point64 unit_step(Point64 a, Point64 b) {
  const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
  const std::int64_t g = std::gcd(std::abs(dx), std::abs(dy));
  return {dx / g, dy / g};
}

// f(p, q) for each of the lattice unit steps p -> q that make up a -> b, in order.
template <class F>
void for_each_unit_step(Point64 a, Point64 b, F&& f) {
  const Point64 u = unit_step(a, b);
  for (Point64 p = a; p != b; p = {p.x + u.x, p.y + u.y}) f(p, Point64{p.x + u.x, p.y + u.y});
}

// An undirected unit step, its ends in lexicographic order.
struct UnitStep {
  Point64 lo, hi;
  friend bool operator==(const UnitStep&, const UnitStep&) = default;
  friend bool operator<(const UnitStep& x, const UnitStep& y) {
    return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi);
  }
};
// +1 when p -> q runs lo -> hi.
inline int step_sign(Point64 p, Point64 q) { return p < q ? 1 : -1; }
inline UnitStep undirected(Point64 p, Point64 q) { return p < q ? UnitStep{p, q} : UnitStep{q, p}; }

// Points just beside the first unit step of a stretch a -> b of an integer arrangement whose
// segments are at most `reach` long (L1). The point lies at distance |u| / (2L) from the step's
// midpoint M (u the step, L = reach^2 + 1), along the normal; every segment of the arrangement
// not containing M is at least 1 / (2 reach) from M (M has a half-integer coordinate, so a
// lattice line missing M is at least 1 / (2 |d|) from it and a lattice point at least 1/2), so
// the point lies in the face beside the step. Coordinates are scaled by 2L to make it integer;
// `scaled` maps the arrangement's points the same way.
class SideProbe {
 public:
  explicit SideProbe(std::int64_t reach)
      : l_(std::max<std::int64_t>(reach, 1) * std::max<std::int64_t>(reach, 1) + 1) {}
  Point64 scaled(Point64 p) const { return checked({2 * l_ * p.x, 2 * l_ * p.y}); }
  Ring scaled(const Ring& ring) const {
    Ring out;
    out.reserve(ring.size());
    for (Point64 p : ring) out.push_back(scaled(p));
    return out;
  }
  Point64 left_of(Point64 a, Point64 b) const {
    const Point64 u = unit_step(a, b);
    return checked({2 * l_ * a.x + l_ * u.x - u.y, 2 * l_ * a.y + l_ * u.y + u.x});
  }
  Point64 right_of(Point64 a, Point64 b) const {
    const Point64 u = unit_step(a, b);
    return left_of({a.x + u.x, a.y + u.y}, a);
  }

 private:
  static Point64 checked(Point64 p) {
    if (std::abs(p.x) > kCoordBound || std::abs(p.y) > kCoordBound)
      throw std::out_of_range("SideProbe: scaled point out of range (inputs too large)");
    return p;
  }
  std::int64_t l_;
};

// The largest L1 length of the segments.
inline std::int64_t reach_of(const std::vector<Segment>& segments) {
  std::int64_t reach = 1;
  for (const Segment& s : segments)
    reach = std::max(reach, std::abs(s.b.x - s.a.x) + std::abs(s.b.y - s.a.y));
  return reach;
}

// The edges, fragments and plane graph of two operands' rings, built as run() builds them
// (stage_outputs.hpp; edges tagged with their ring's index; noding without screen or overlap
// budget). Not movable: the graph keeps pointers into the edge list.
struct Arrangement : detail::StageOutputs {
  Arrangement(const std::vector<Ring>& subject, const std::vector<Ring>& clip, bool simple_rings) {
    detail::append_ring_edges(subject, detail::kSubjectChannel, true, edges);
    detail::append_ring_edges(clip, detail::kClipChannel, true, edges);
    detail::plane_graph_stages(*this, simple_rings);
  }
  Arrangement(const Arrangement&) = delete;
  Arrangement& operator=(const Arrangement&) = delete;
};

// Every fragment of segment s, in order: the listed ones, or the segment itself.
inline std::vector<std::vector<Segment>> fragments_by_segment(
    const detail::EdgeList& edges, const std::vector<detail::Fragment>& listed) {
  std::vector<std::vector<Segment>> of(edges.size());
  for (const detail::Fragment& f : listed) of[f.parent].push_back(f.seg);
  for (std::uint32_t s = 0; s < edges.size(); ++s)
    if (of[s].empty()) of[s].push_back(edges.segments[s]);
  return of;
}

// The rings of an edge list (edges of a ring are consecutive, next[] cycles through them):
// [begin, end) of each.
inline std::vector<std::pair<std::uint32_t, std::uint32_t>> ring_spans(
    const detail::EdgeList& edges) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> spans;
  for (std::uint32_t b = 0; b < edges.size();) {
    std::uint32_t e = b;
    while (edges.next[e] != b) ++e;
    spans.push_back({b, e + 1});
    b = e + 1;
  }
  return spans;
}

// An input ring as snap rounding left it: the starts of its segments' fragments, in order.
struct SnappedRing {
  std::uint8_t channel;
  std::int32_t polygon;
  Ring points;
};

inline std::vector<SnappedRing> snapped_rings(const Arrangement& a) {
  const auto of = fragments_by_segment(a.edges, a.fragments);
  std::vector<SnappedRing> rings;
  for (const auto& [b, e] : ring_spans(a.edges)) {
    SnappedRing r{a.edges.channel[b], a.edges.polygon[b], {}};
    for (std::uint32_t s = b; s < e; ++s)
      for (const Segment& f : of[s]) r.points.push_back(f.a);
    rings.push_back(std::move(r));
  }
  return rings;
}

// Brute-force states of the faces of an arrangement: the winding numbers of its snapped rings
// about points just beside a stretch (SideProbe), summed (kWinding) or read as the owning
// polygon per channel (kOwner).
class BruteStates {
 public:
  explicit BruteStates(const Arrangement& a) : probe_(reach(a)) {
    for (SnappedRing& r : snapped_rings(a)) {
      r.points = probe_.scaled(r.points);
      rings_.push_back(std::move(r));
    }
  }
  const SideProbe& probe() const { return probe_; }

  // Winding number of each snapped ring about the scaled point q (not on any ring).
  std::vector<int> windings(Point64 q) const {
    std::vector<int> w;
    w.reserve(rings_.size());
    for (const SnappedRing& r : rings_) w.push_back(winding_number(q, r.points));
    return w;
  }
  detail::SideState winding_state(Point64 q) const {
    int sum = 0;
    for (int w : windings(q)) sum += w;
    detail::SideState s = detail::empty_state(detail::LabelMode::kWinding);
    s.by_channel[0] = sum;
    return s;
  }
  // The polygon of each channel whose ring winds once about q; nullopt when some ring winds
  // otherwise than 0 or 1 times, or two of one channel wind about it (not a valid operand).
  std::optional<detail::SideState> owner_state(Point64 q) const {
    detail::SideState s = detail::empty_state(detail::LabelMode::kOwner);
    const std::vector<int> w = windings(q);
    for (std::size_t i = 0; i < rings_.size(); ++i) {
      if (w[i] == 0) continue;
      std::int32_t& owner = s.by_channel[rings_[i].channel];
      if (w[i] != 1 || owner >= 0) return std::nullopt;
      owner = rings_[i].polygon;
    }
    return s;
  }
  // The sum of the winding numbers about q of the rings of one channel.
  int cover(Point64 q, std::uint8_t channel) const {
    int sum = 0;
    const std::vector<int> w = windings(q);
    for (std::size_t i = 0; i < rings_.size(); ++i)
      if (rings_[i].channel == channel) sum += w[i];
    return sum;
  }
  int max_cover(Point64 q) const { return std::max(cover(q, 0), cover(q, 1)); }

 private:
  static std::int64_t reach(const Arrangement& a) {
    std::vector<Segment> all = a.edges.segments;
    for (const detail::Fragment& f : a.fragments) all.push_back(f.seg);
    return reach_of(all);
  }
  SideProbe probe_;
  std::vector<SnappedRing> rings_;
};

}  // namespace edgeland::test::stages
