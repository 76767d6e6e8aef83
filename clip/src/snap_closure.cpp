// Snap rounding's hot-set closure (snap_rounding_steps.hpp). Grows the hot set until closed:
//  * every segment meeting a hot pixel off its centre is moved (routed through the centre);
//  * stable rule: a vertex becomes hot when the route of a moved segment would jump over it,
//    i.e. it lies strictly inside the region between the segment and its route (the closed
//    polyline route + segment winds around it). Only such a vertex could end up on the other
//    side of the snapped segment; vertices merely near the segment are left alone, which is
//    what keeps far edges unchanged (locality);
//  * classic rule (fallback): every vertex pixel a moved segment meets becomes hot, as in
//    Guibas-Marimont snap rounding, whose theorem guarantees no new crossing.
// Vertices are the segments' endpoints and the exact split points. Either rule can only pin a
// vertex whose closed pixel the segment meets: the route's corners are centres of pixels the
// segment meets, so the region between them lies within half a unit (in x and y) of the segment.
// Each round only looks at what is new.
#include <algorithm>
#include <optional>

#include "box_sweep.hpp"
#include "edgeland/kernel/pixel.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "snap_rounding_steps.hpp"

namespace edgeland::detail::snap_steps {
namespace {

ScratchVector<Box64> pixel_boxes(const std::vector<Point64>& pts) {
  ScratchVector<Box64> boxes;
  boxes.resize(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) boxes[i] = pixel_box(pts[i]);
  return boxes;
}

// The polyline a segment is routed along, into r: its ends, its exact split points and the
// centres of the hot pixels it meets (`stops`, sorted here), in order along it.
void route_of(const Segment& seg, std::vector<Point64>& stops, Ring& r) {
  std::sort(stops.begin(), stops.end(), [&](Point64 x, Point64 y) {
    const Int128 px = projection(seg, x), py = projection(seg, y);
    return px != py ? px < py : x < y;
  });
  r.assign(1, seg.a);
  for (Point64 p : stops)
    if (p != r.back() && p != seg.b) r.push_back(p);
  r.push_back(seg.b);
}

// Whether a batch of `queries` (points or segments) against `segments` segments is large
// enough that asking the segment grid at each point, or a pass over all vertices, beats box
// queries into the run index.
bool large_batch(std::size_t queries, std::size_t segments) {
  return queries > 64 && 8 * queries > segments;
}

// One closure: rounds of meeting the fresh hot pixels, then pinning the vertices the segments
// they moved would jump over, until a round pins nothing new.
class HotSetClosure {
 public:
  HotSetClosure(const ClosureInput& in, bool classic, PointSet& is_hot, Closure& c)
      : in_(in), segs_(in.segs), classic_(classic), is_hot_(is_hot), c_(c) {}

  void run(std::vector<Point64>& fresh) {
    while (!fresh.empty()) {
      meet_fresh(fresh);
      fresh.clear();
      keep_moved_once();
      if (changed_.empty()) break;
      routes_.clear();
      routes_.resize(changed_.size());
      hot_stops_.reset();
      if (large_batch(changed_.size(), segs_.size())) {
        pin_by_vertex_pass(fresh);
      } else {
        pin_by_box_queries(fresh);
      }
      std::sort(fresh.begin(), fresh.end());  // deterministic order, independent of hashing
    }
  }

 private:
  static constexpr std::uint32_t kNoSlot = 0xffffffffu;

  void meet_fresh(const std::vector<Point64>& fresh);
  void keep_moved_once();
  const Ring& route(std::uint32_t k);
  void pin_if_needed(std::uint32_t k, Point64 p, bool on, std::vector<Point64>& fresh);
  void consider(std::uint32_t k, Point64 p, std::vector<Point64>& fresh);
  void pin_by_vertex_pass(std::vector<Point64>& fresh);
  void pin_by_box_queries(std::vector<Point64>& fresh);

  const ClosureInput& in_;
  const std::vector<Segment>& segs_;
  const bool classic_;
  PointSet& is_hot_;
  Closure& c_;
  ScratchVector<std::uint32_t> changed_;  // segments met this round
  // Of changed_[k], built when first asked for (empty until then).
  ScratchVector<ScratchVector<Point64>> routes_;
  std::optional<StopsOf> hot_stops_;     // every hot centre met so far, by segment
  ScratchVector<SweepBox> split_sweep_;  // the split points' pixel boxes, sorted when first needed
  ScratchVector<std::uint32_t> slot_;    // segment -> its place in changed_, or kNoSlot
};

// Adds the fresh centres to the hot set and records every segment meeting their pixels.
void HotSetClosure::meet_fresh(const std::vector<Point64>& fresh) {
  const auto base = static_cast<std::uint32_t>(c_.hot.size());
  c_.hot.insert(c_.hot.end(), fresh.begin(), fresh.end());
  changed_.clear();
  auto meet = [&](std::uint32_t h, std::uint32_t s) {
    const Point64 centre = fresh[h];
    if (!segment_meets_pixel(segs_[s], centre)) return;
    c_.meets.emplace_back(s, base + h);
    if (!on_segment(centre, segs_[s])) c_.moved[s] = true;
    changed_.push_back(s);
  };
  if (in_.search.near.has_grid() || large_batch(fresh.size(), segs_.size())) {
    // Many hot pixels (spiky inputs: long segments crossing everywhere, whose boxes cover half
    // the input), or a segment grid noding already built: each pixel asks the grid for the
    // segments through its cells.
    for (std::uint32_t h = 0; h < fresh.size(); ++h)
      in_.search.near.for_each(fresh[h], [&](std::uint32_t s) { meet(h, s); });
  } else {
    in_.search.index.query(pixel_boxes(fresh), meet);
  }
}

// changed_: each segment met once, in increasing order, and only the moved ones.
void HotSetClosure::keep_moved_once() {
  if (changed_.size() > segs_.size()) {  // many meetings: mark and list in order, no sort
    ScratchVector<std::uint8_t> met_now;
    met_now.assign(segs_.size(), false);
    for (std::uint32_t s : changed_) met_now[s] = true;
    changed_.clear();
    for (std::uint32_t s = 0; s < segs_.size(); ++s)
      if (met_now[s]) changed_.push_back(s);
  } else {
    std::sort(changed_.begin(), changed_.end());
    changed_.erase(std::unique(changed_.begin(), changed_.end()), changed_.end());
  }
  changed_.erase(std::remove_if(changed_.begin(), changed_.end(),
                                [&](std::uint32_t s) { return !c_.moved[s]; }),
                 changed_.end());
}

// The route of changed_[k]. Built when first asked for: a vertex on the segment itself (its
// ends, its split points) lies on the boundary of the region between segment and route, never
// strictly inside, so on spiky inputs most moved segments never need theirs.
const Ring& HotSetClosure::route(std::uint32_t k) {
  if (!routes_[k].empty()) return routes_[k];
  if (!hot_stops_) {
    ScratchVector<SegmentPoint> met;
    met.reserve(c_.meets.size());
    for (const auto& [s, h] : c_.meets) met.emplace_back(s, c_.hot[h]);
    hot_stops_.emplace(segs_.size(), met);
  }
  ScratchVector<Point64> stops;
  hot_stops_->append(changed_[k], stops);
  in_.splits_of.append(changed_[k], stops);
  route_of(segs_[changed_[k]], stops, routes_[k]);
  return routes_[k];
}

// Vertex p, whose closed pixel changed segment k meets (`on`: p lies on the segment): pinned if
// the rule says so.
void HotSetClosure::pin_if_needed(std::uint32_t k, Point64 p, bool on,
                                  std::vector<Point64>& fresh) {
  if ((!classic_ && on) || is_hot_.contains(p)) return;
  const bool pin = classic_ ? segment_meets_pixel(segs_[changed_[k]], p)
                            : locate(p, route(k)) == PointLocation::kInside;
  if (!pin) return;
  is_hot_.insert(p);
  fresh.push_back(p);
}

void HotSetClosure::consider(std::uint32_t k, Point64 p, std::vector<Point64>& fresh) {
  const Segment& seg = segs_[changed_[k]];
  if (segment_meets_closed_pixel(seg, p)) pin_if_needed(k, p, on_segment(p, seg), fresh);
}

// Every vertex asks for the changed segments near it (a pass over all vertices: only when the
// changed segments are many). The first such pass also records which segments pass near which
// vertices, for the re-check (off_classic_routes), at the price of one more exact test per
// candidate.
void HotSetClosure::pin_by_vertex_pass(std::vector<Point64>& fresh) {
  slot_.assign(segs_.size(), kNoSlot);
  for (std::uint32_t k = 0; k < changed_.size(); ++k) slot_[changed_[k]] = k;
  const bool record = !c_.near_vertex_complete;
  auto at_vertex = [&](Point64 p) {
    in_.search.near.for_each(p, [&](std::uint32_t s) {
      if ((slot_[s] == kNoSlot && !record) || !segment_meets_closed_pixel(segs_[s], p)) return;
      const bool on = on_segment(p, segs_[s]);
      if (record && !on) c_.near_vertex.emplace_back(s, p);
      if (slot_[s] != kNoSlot) pin_if_needed(slot_[s], p, on, fresh);
    });
  };
  for (const Segment& seg : segs_) at_vertex(seg.a);  // every end starts a segment
  for (Point64 p : in_.split_points) at_vertex(p);
  c_.near_vertex_complete = true;
}

// A few changed segments: box queries for the segment ends near them, a sweep for the split
// points.
void HotSetClosure::pin_by_box_queries(std::vector<Point64>& fresh) {
  ScratchVector<Box64> boxes;
  boxes.resize(changed_.size());
  for (std::size_t k = 0; k < changed_.size(); ++k)
    boxes[k] = grown(in_.search.index.box(changed_[k]), 1);
  in_.search.index.query(boxes, [&](std::uint32_t k, std::uint32_t t) {
    consider(k, segs_[t].a, fresh);
    consider(k, segs_[t].b, fresh);
  });
  if (split_sweep_.empty() && !in_.split_points.empty())
    sort_for_sweep(pixel_boxes(in_.split_points), split_sweep_);
  if (split_sweep_.empty()) return;
  for_each_overlapping_pair(
      sorted_for_sweep(boxes), split_sweep_,
      [&](std::uint32_t k, std::uint32_t v) { consider(k, in_.split_points[v], fresh); });
}

}  // namespace

void close_hot_set(const ClosureInput& in, bool classic, PointSet& is_hot, Closure& c,
                   std::vector<Point64>& fresh) {
  HotSetClosure(in, classic, is_hot, c).run(fresh);
}

}  // namespace edgeland::detail::snap_steps
