#include "ring_check.hpp"

#include <algorithm>
#include <cstdint>
#include <set>
#include <tuple>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/validate.hpp"

namespace edgeland::bench {
namespace {

std::string where(Point64 p) { return "(" + std::to_string(p.x) + " " + std::to_string(p.y) + ")"; }

struct Edge {
  Segment segment;
  Box64 box;
  std::size_t ring;
};

// Counter-clockwise angular order of nonzero direction vectors, starting at +x.
bool angle_less(Point64 u, Point64 v) {
  const bool u_lower = u.y < 0 || (u.y == 0 && u.x < 0);
  const bool v_lower = v.y < 0 || (v.y == 0 && v.x < 0);
  if (u_lower != v_lower) return !u_lower;
  return static_cast<Int128>(u.x) * v.y - static_cast<Int128>(u.y) * v.x > 0;
}

// Whether direction d lies strictly inside the counter-clockwise wedge from a to b.
bool in_wedge(Point64 a, Point64 b, Point64 d) {
  if (angle_less(a, b)) return angle_less(a, d) && angle_less(d, b);
  return angle_less(a, d) || angle_less(d, b);
}

// The directions in which the boundary of `ring` leaves point p (two for a simple ring
// through p).
std::vector<Point64> directions_at(const Ring& ring, Point64 p) {
  std::vector<Point64> out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Segment e = ring_edge(ring, i);
    const bool start = e.a == p;
    const bool end = e.b == p;
    if (start || on_segment_interior(p, e)) out.push_back({e.b.x - p.x, e.b.y - p.y});
    if (end || on_segment_interior(p, e)) out.push_back({e.a.x - p.x, e.a.y - p.y});
  }
  return out;
}

// Two simple rings meeting at p without overlapping there cross iff the directions of one
// separate the directions of the other.
bool cross_at(const Ring& r, const Ring& s, Point64 p) {
  const std::vector<Point64> a = directions_at(r, p);
  const std::vector<Point64> b = directions_at(s, p);
  if (a.size() != 2 || b.size() != 2) return true;  // cannot happen for simple rings
  return in_wedge(a[0], a[1], b[0]) != in_wedge(a[0], a[1], b[1]);
}

RingCheck pairwise(const std::vector<Ring>& all) {
  std::vector<Edge> edges;
  for (std::size_t r = 0; r < all.size(); ++r) {
    for (std::size_t i = 0; i < all[r].size(); ++i) {
      const Segment s = ring_edge(all[r], i);
      Box64 box{s.a, s.a};
      box.expand(s.b);
      edges.push_back({s, box, r});
    }
  }
  std::sort(edges.begin(), edges.end(),
            [](const Edge& a, const Edge& b) { return a.box.min.x < b.box.min.x; });
  std::set<std::tuple<std::size_t, std::size_t, Point64>> touches;
  std::vector<const Edge*> active;
  for (const Edge& e : edges) {
    std::erase_if(active, [&](const Edge* a) { return a->box.max.x < e.box.min.x; });
    for (const Edge* a : active) {
      if (a->ring == e.ring || !a->box.overlaps(e.box)) continue;
      const SegmentIntersection hit = intersect(a->segment, e.segment);
      switch (hit.relation) {
        case SegmentRelation::kDisjoint:
          break;
        case SegmentRelation::kCrossing:
          return {false, "rings " + std::to_string(a->ring) + " and " + std::to_string(e.ring) +
                             " cross near " + where(round_to_grid(hit.point))};
        case SegmentRelation::kOverlapping:
          return {false, "rings " + std::to_string(a->ring) + " and " + std::to_string(e.ring) +
                             " overlap from " + where(hit.overlap_from) + " to " +
                             where(hit.overlap_to)};
        case SegmentRelation::kTouching:
          touches.insert(
              {std::min(a->ring, e.ring), std::max(a->ring, e.ring), round_to_grid(hit.point)});
          break;
      }
    }
    active.push_back(&e);
  }
  for (const auto& [r, s, p] : touches) {
    if (cross_at(all[r], all[s], p)) {
      return {false, "rings " + std::to_string(r) + " and " + std::to_string(s) +
                         " cross at their common point " + where(p)};
    }
  }
  return {};
}

}  // namespace

PeerRings without_repeated_vertices(PeerRings rings) {
  auto clean = [](std::vector<Ring>& list) {
    for (Ring& ring : list) {
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
      while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
    }
    std::erase_if(list, [](const Ring& ring) { return ring.size() < 3; });
  };
  clean(rings.outers);
  clean(rings.holes);
  return rings;
}

RingCheck check_rings(const PeerRings& rings) {
  if (rings.holes.empty()) {
    const ValidationReport report = validate(rings.outers, 1);
    if (report.ok()) return {};
    return {false, report.violations.front().describe()};
  }
  std::vector<Ring> all = rings.outers;
  all.insert(all.end(), rings.holes.begin(), rings.holes.end());
  for (std::size_t r = 0; r < all.size(); ++r) {
    const ValidationReport report = validate(all[r], 1);
    if (!report.ok()) {
      return {false, "ring " + std::to_string(r) +
                         (r < rings.outers.size() ? " (outer)" : " (hole)") + ": " +
                         report.violations.front().describe()};
    }
  }
  return pairwise(all);
}

}  // namespace edgeland::bench
