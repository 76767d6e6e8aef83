#include "edgeland/kernel/boundary_intersections.hpp"

#include <optional>
#include <utility>

namespace edgeland {
namespace {

constexpr int sign(Int128 v) noexcept { return (v > 0) - (v < 0); }

RationalPoint integer_point(Point64 p) noexcept { return RationalPoint{p.x, p.y, 1}; }

bool is_point(const RationalPoint& r, Point64 p) noexcept {
  return r.x_num == Int128(p.x) * r.den && r.y_num == Int128(p.y) * r.den;
}

BoundaryHit point_hit(std::size_t edge, const RationalPoint& p) noexcept {
  BoundaryHit h;
  h.edge = edge;
  h.kind = BoundaryHitKind::kPoint;
  h.point = p;
  return h;
}

BoundaryHit overlap_hit(std::size_t edge, Point64 from, Point64 to) noexcept {
  BoundaryHit h;
  h.edge = edge;
  h.kind = BoundaryHitKind::kOverlap;
  h.overlap_from = from;
  h.overlap_to = to;
  return h;
}

// The closed edge against the closed query segment.
std::optional<BoundaryHit> segment_meets_edge(const Segment& query, const Segment& edge,
                                              std::size_t index) noexcept {
  const SegmentIntersection r = intersect(edge, query);
  switch (r.relation) {
    case SegmentRelation::kDisjoint:
      return std::nullopt;
    case SegmentRelation::kCrossing:
    case SegmentRelation::kTouching:
      return point_hit(index, r.point);
    case SegmentRelation::kOverlapping:
      // intersect() orders the overlap lexicographically; report it along the edge.
      if (edge.b < edge.a) return overlap_hit(index, r.overlap_to, r.overlap_from);
      return overlap_hit(index, r.overlap_from, r.overlap_to);
  }
  return std::nullopt;  // Not reached by tests: the switch covers every SegmentRelation.
}

// The closed edge against the infinite line through line.a != line.b.
std::optional<BoundaryHit> line_meets_edge(const Segment& line, const Segment& edge,
                                           std::size_t index) noexcept {
  const int sa = sign(orient_det(line.a, line.b, edge.a));
  const int sb = sign(orient_det(line.a, line.b, edge.b));
  if (sa == 0 && sb == 0) return overlap_hit(index, edge.a, edge.b);
  if (sa * sb > 0) return std::nullopt;
  if (sb == 0) return point_hit(index, integer_point(edge.b));
  if (sa == 0) return point_hit(index, integer_point(edge.a));
  return point_hit(index, *line_intersection(edge, line));  // not parallel: signs differ
}

// The next edge after i (cyclically) whose length is positive; i itself if there is none.
std::size_t next_proper_edge(const Ring& ring, std::size_t i) noexcept {
  const std::size_t n = ring.size();
  for (std::size_t step = 1; step < n; ++step) {
    const std::size_t j = (i + step) % n;
    if (ring[j] != ring[(j + 1) % n]) return j;
  }
  // Not reached by tests: i is always a proper edge, and a ring that leaves a point along one
  // comes back to it along another, so the loop finds one.
  return i;
}

// Thesis figure 9 with half-open edges, plus the convex early exit of 2.4.1.
template <class MeetsEdge>
std::vector<BoundaryHit> scan(const Ring& ring, RingShape shape, MeetsEdge meets) {
  const std::size_t n = ring.size();
  std::vector<BoundaryHit> hits;
  std::size_t points = 0;
  bool in_run = false;          // the previous proper edge reported an overlap
  bool first_edge_hit = false;  // the first proper edge reported something (a run may wrap)
  bool seen_proper_edge = false;
  for (std::size_t i = 0; i < n; ++i) {
    const Segment edge = ring_edge(ring, i);
    if (edge.a == edge.b) continue;  // a zero-length edge is empty when half-open
    std::optional<BoundaryHit> hit = meets(edge, i);
    const bool first = !seen_proper_edge;
    seen_proper_edge = true;
    if (hit && hit->kind == BoundaryHitKind::kPoint && is_point(hit->point, edge.a)) {
      hit.reset();  // the start vertex belongs to the previous edge
    }
    if (first && hit) first_edge_hit = true;
    const bool overlap = hit && hit->kind == BoundaryHitKind::kOverlap;
    if (hit) {
      if (!overlap) ++points;
      hits.push_back(*hit);
    }
    if (shape == RingShape::kConvex) {
      // A convex boundary shares with a line at most two points or one run of collinear
      // edges; once that is complete nothing else can follow. A run that touches the first
      // edge may continue at the end of the ring, so it never ends the scan early.
      if (points == 2) break;
      if (in_run && !overlap && !first_edge_hit) break;
    }
    in_run = overlap;
  }
  // A point hit at the end vertex of edge i is already covered when the next proper edge
  // reports an overlap starting there.
  std::vector<BoundaryHit> out;
  out.reserve(hits.size());
  for (std::size_t k = 0; k < hits.size(); ++k) {
    const BoundaryHit& h = hits[k];
    if (h.kind == BoundaryHitKind::kPoint && is_point(h.point, ring[(h.edge + 1) % n])) {
      // Edges between h.edge and `next` have zero length and report nothing, so the next
      // proper edge's hit, if any, is the next entry of the list.
      const std::size_t next = next_proper_edge(ring, h.edge);
      const BoundaryHit& following = hits[(k + 1) % hits.size()];
      if (following.edge == next && following.kind == BoundaryHitKind::kOverlap) continue;
    }
    out.push_back(h);
  }
  return out;
}

}  // namespace

std::vector<BoundaryHit> boundary_intersections(const Segment& query, const Ring& ring,
                                                RingShape shape) {
  return scan(ring, shape, [&query](const Segment& edge, std::size_t i) {
    return segment_meets_edge(query, edge, i);
  });
}

std::vector<BoundaryHit> line_boundary_intersections(const Segment& line, const Ring& ring,
                                                     RingShape shape) {
  if (line.a == line.b) return boundary_intersections(line, ring, shape);
  return scan(ring, shape, [&line](const Segment& edge, std::size_t i) {
    return line_meets_edge(line, edge, i);
  });
}

}  // namespace edgeland
