// merge_tiles (clip.hpp): the union of a valid set's members without the general pipeline.
// Members of a valid set have disjoint interiors, so their boundaries never cross: they meet at
// points and along collinear stretches only. Stages, each handing the next what it needs:
//   1. boundary stretches: the members' directed edges grouped by supporting line; on each
//      line the net direction of the edges over every stretch between their end points (+1,
//      -1 or 0: two members covering a stretch the same way would overlap), so stretches two
//      members share cancel and every stretch left has the union's inside on its left;
//   1b. touching ends: a member's vertex may touch another member's edge inside it, off the
//      edge's line (a T-junction: the members meet at that point only); the union's boundary
//      passes that point twice, so each stretch is split at every stretch end lying inside it
//      (the tracing then meets the point as a vertex, and splits the walk there);
//   2. faces: the stretches traced by the sharpest-left-turn rule (face_tracing.hpp), walks
//      split where they revisit a point: counter-clockwise outer rings and clockwise holes;
//   3. the rings reduced to their corners and the points two rings touch at (what hole
//      splitting may bridge to, as assembly's corner bridges), holes split (hole_splitting.hpp),
//      each piece in canonical form, the pieces sorted.
// TileMerge runs stages 1-2 in its constructor and stage 3 in finish(), owning the rings between
// (a game spreads a big island's merge over two frames); merge_tiles is the two at once.
// Nothing is rounded: every output vertex is a member's vertex. In checked mode the result is
// validated and its area compared with the members' sum, exactly.
#include <algorithm>
#include <cstdint>
#include <utility>

#include "canonical.hpp"
#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/supporting_line.hpp"
#include "face_tracing.hpp"
#include "hole_splitting.hpp"
#include "valid_set_factory.hpp"

namespace edgeland {
namespace detail {
namespace {

// A directed edge on its supporting line (the kernel's key: reduced direction and exact offset),
// its end points placed along the line by position_on().
struct LineEdge {
  SupportingLine line;
  std::int64_t from = 0, to = 0;
  Point64 a, b;
  bool operator<(const LineEdge& o) const { return line < o.line; }
};

LineEdge line_edge(Point64 a, Point64 b) {
  const SupportingLine line = supporting_line(a, b);
  return {line, position_on(line, a), position_on(line, b), a, b};
}

// One end point of an edge of a line: where the net direction changes by `delta`.
struct LineEvent {
  std::int64_t at;
  Point64 point;
  int delta;
};

// The stretches of one line (edges [first, last) of it) with a net direction, appended to `out`.
void net_stretches(const LineEdge* first, const LineEdge* last, std::vector<Segment>& out,
                   std::vector<LineEvent>& events) {
  events.clear();
  for (const LineEdge* e = first; e != last; ++e) {
    const bool forward = e->from < e->to;
    events.push_back({forward ? e->from : e->to, forward ? e->a : e->b, forward ? 1 : -1});
    events.push_back({forward ? e->to : e->from, forward ? e->b : e->a, forward ? -1 : 1});
  }
  std::sort(events.begin(), events.end(),
            [](const LineEvent& l, const LineEvent& r) { return l.at < r.at; });
  int net = 0;
  for (std::size_t i = 0; i < events.size();) {
    std::size_t j = i;  // every event at one position before the net is read
    for (; j < events.size() && events[j].at == events[i].at; ++j) net += events[j].delta;
    if (net < -1 || net > 1) fail_stage("tile merge", "two members cover a stretch the same way");
    if (net != 0 && j < events.size()) {
      const Point64 p = events[i].point, q = events[j].point;
      out.push_back(net > 0 ? Segment{p, q} : Segment{q, p});
    }
    i = j;
  }
}

// Stage 1: the union's boundary as directed stretches (inside on the left).
std::vector<Segment> boundary_stretches(const PolygonSet& members) {
  std::vector<LineEdge> edges;
  for (const Polygon& p : members)
    for (std::size_t i = 0; i < p.size(); ++i)
      edges.push_back(line_edge(p[i], p[(i + 1) % p.size()]));
  std::sort(edges.begin(), edges.end());
  std::vector<Segment> out;
  std::vector<LineEvent> events;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].line == edges[i].line) ++j;
    if (j == i + 1)
      out.push_back({edges[i].a, edges[i].b});  // alone on its line: kept as it is
    else
      net_stretches(edges.data() + i, edges.data() + j, out, events);
    i = j;
  }
  return out;
}

// The ends lying inside the stretches (on_segment_interior), as (stretch, point) pairs ordered
// by stretch and then from its a to its b. The stretches are visited by the west side of their
// box, so the sorted ends are read by one pointer that only moves east, without a search per
// stretch (binary searches were most of this stage on a wide island); a stretch's candidates
// are the ends between its box's x bounds, passed over by comparisons outside its y bounds.
std::vector<std::pair<std::uint32_t, Point64>> ends_inside(const std::vector<Segment>& stretches) {
  std::vector<Point64> ends;
  ends.reserve(2 * stretches.size());
  for (const Segment& s : stretches) ends.insert(ends.end(), {s.a, s.b});
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  std::vector<std::pair<std::int64_t, std::uint32_t>> by_west(stretches.size());
  for (std::uint32_t i = 0; i < stretches.size(); ++i)
    by_west[i] = {std::min(stretches[i].a.x, stretches[i].b.x), i};
  std::sort(by_west.begin(), by_west.end());
  std::vector<std::pair<std::uint32_t, Point64>> out;
  auto first = ends.begin();
  for (const auto& [west, i] : by_west) {
    const Segment& s = stretches[i];
    const Box64 box = segment_box(s);
    while (first != ends.end() && first->x < west) ++first;
    for (auto it = first; it != ends.end() && it->x <= box.max.x; ++it)
      if (it->y >= box.min.y && it->y <= box.max.y && on_segment_interior(*it, s))
        out.push_back({i, *it});
  }
  // Collinear points sort along a segment by (x, y); reversed where it runs the other way.
  std::sort(out.begin(), out.end());
  for (auto at = out.begin(); at != out.end();) {
    const auto end =
        std::find_if(at, out.end(), [&](const auto& e) { return e.first != at->first; });
    const Segment& s = stretches[at->first];
    if (s.b < s.a) std::reverse(at, end);
    at = end;
  }
  return out;
}

// Stage 1b: every stretch split at the stretch ends lying inside it.
void split_at_touching_ends(std::vector<Segment>& stretches) {
  const std::vector<std::pair<std::uint32_t, Point64>> inside = ends_inside(stretches);
  if (inside.empty()) return;
  std::vector<Segment> split;
  split.reserve(stretches.size() + inside.size());
  auto next = inside.begin();
  for (std::uint32_t i = 0; i < stretches.size(); ++i) {
    Point64 from = stretches[i].a;
    for (; next != inside.end() && next->first == i; ++next)
      split.push_back({std::exchange(from, next->second), next->second});
    split.push_back({from, stretches[i].b});
  }
  stretches = std::move(split);
}

// Points of more than one ring, sorted: where hole splitting may bridge to beside corners.
std::vector<Point64> shared_points(const std::vector<ScratchRing>& a,
                                   const std::vector<ScratchRing>& b) {
  std::vector<Point64> all;
  for (const auto* rings : {&a, &b})
    for (const ScratchRing& r : *rings) all.insert(all.end(), r.begin(), r.end());
  std::sort(all.begin(), all.end());
  std::vector<Point64> shared;
  for (std::size_t i = 1; i < all.size(); ++i)
    if (all[i] == all[i - 1] && (shared.empty() || shared.back() != all[i]))
      shared.push_back(all[i]);
  return shared;
}

void reduce_to_corners(std::vector<ScratchRing>& rings, const std::vector<Point64>& keep) {
  Ring ring;
  for (ScratchRing& r : rings) {
    ring.assign(r.begin(), r.end());
    drop_collinear_except(ring, keep);
    r.assign(ring.begin(), ring.end());
  }
}

// Stage 2: the faces of the stretches, counter-clockwise outer rings and clockwise holes.
void rings_of(const std::vector<Segment>& stretches, std::vector<Ring>& outers,
              std::vector<Ring>& holes) {
  ScratchVector<ScratchRing> faces;
  trace_faces(stretches, faces);
  for (ScratchRing& f : faces) {
    const Int128 area = twice_signed_area(f);
    if (area == 0) fail_stage("tile merge", "a traced face has no area");
    (area > 0 ? outers : holes).emplace_back(f.begin(), f.end());
  }
}

// Stage 3: the rings reduced to corners and shared points, holes split, the pieces canonical
// and sorted.
PolygonSet pieces_of(const std::vector<Ring>& outer_rings, const std::vector<Ring>& hole_rings,
                     std::size_t& holes_split) {
  ScratchVector<ScratchRing> outers, holes;
  for (const Ring& r : outer_rings) outers.emplace_back().assign(r.begin(), r.end());
  for (const Ring& r : hole_rings) holes.emplace_back().assign(r.begin(), r.end());
  if (!holes.empty()) {
    const std::vector<Point64> keep = shared_points(outers, holes);
    reduce_to_corners(outers, keep);
    reduce_to_corners(holes, keep);
  }
  std::vector<Ring> rings;
  split_holes(outers, holes, holes_split, rings);
  PolygonSet out;
  out.reserve(rings.size());
  for (Ring& r : rings) out.push_back(canonical_ring(std::move(r)));
  sort_canonical(out);
  return out;
}

void check_tiles_merged(const Int128& members_twice_area, const PolygonSet& merged) {
  const ValidationReport report = validate(merged, 1);
  if (!report.ok()) fail_stage("tile merge", report.violations[0].describe());
  if (twice_signed_area(merged) != members_twice_area)
    fail_stage("tile merge", "the union's area is not the members' sum");
}

}  // namespace
}  // namespace detail

ValidClipResult merge_tiles(const ValidSet& set, const ClipOptions& options) {
  return TileMerge(set, options).finish();
}

// Stages 1, 1b and 2.
TileMerge::TileMerge(const ValidSet& set, const ClipOptions& options) : options_(options) {
  std::vector<Segment> stretches = detail::boundary_stretches(set.polygons());
  detail::split_at_touching_ends(stretches);
  detail::rings_of(stretches, outers_, holes_);
  if (options.checked) twice_area_ = twice_signed_area(set.polygons());
}

std::size_t TileMerge::ring_vertices() const noexcept {
  std::size_t n = 0;
  for (const auto* rings : {&outers_, &holes_})
    for (const Ring& r : *rings) n += r.size();
  return n;
}

// Stage 3.
ValidClipResult TileMerge::finish() && {
  ClipResult out;
  out.polygons = detail::pieces_of(outers_, holes_, out.stats.holes_split);
  if (options_.checked) detail::check_tiles_merged(twice_area_, out.polygons);
  return ValidSetFactory::from(std::move(out));
}

}  // namespace edgeland
