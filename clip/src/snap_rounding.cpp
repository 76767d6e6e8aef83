#include "snap_rounding.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <utility>

#include "box_grid.hpp"
#include "box_sweep.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/pixel.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "noding.hpp"
#include "point_set.hpp"
#include "radix_sort.hpp"
#include "segment_grid.hpp"
#include "segment_index.hpp"

namespace edgeland::detail {
namespace {

// Points on the way of segments, grouped by segment (CSR: one array, no allocation per segment).
class StopsOf {
 public:
  StopsOf(std::size_t segments, const std::vector<std::pair<std::uint32_t, Point64>>& stops) {
    begin_.assign(segments + 1, 0);
    points_.resize(stops.size());
    for (const auto& st : stops) ++begin_[st.first + 1];
    for (std::size_t k = 1; k < begin_.size(); ++k) begin_[k] += begin_[k - 1];
    RecycledVector<struct StopsFillBuffer, std::uint32_t> fill;
    fill.assign(begin_.begin(), begin_.end() - 1);
    for (const auto& [s, p] : stops) points_[fill[s]++] = p;
  }
  // Appends the points of segment s to out.
  void append(std::uint32_t s, std::vector<Point64>& out) const {
    out.insert(out.end(), points_.begin() + begin_[s], points_.begin() + begin_[s + 1]);
  }

 private:
  RecycledVector<struct StopsBeginBuffer, std::uint32_t> begin_;
  RecycledVector<struct StopsPointsBuffer, Point64> points_;
};

// A box that contains the whole pixel of p (closed, integer corners).
Box64 pixel_box(Point64 p) { return Box64{{p.x - 1, p.y - 1}, {p.x + 1, p.y + 1}}; }

std::vector<Box64> pixel_boxes(const std::vector<Point64>& pts) {
  std::vector<Box64> boxes(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) boxes[i] = pixel_box(pts[i]);
  return boxes;
}

struct Closure {
  RecycledVector<struct ClosureHotBuffer, Point64> hot;  // all hot pixel centres
  // (segment, hot index)
  RecycledVector<struct ClosureMeetsBuffer, std::pair<std::uint32_t, std::uint32_t>> meets;
  RecycledVector<struct ClosureMovedBuffer, std::uint8_t> moved;
  // (segment, vertex) for every vertex (end or split point) not on the segment whose closed pixel
  // the segment meets; complete once a grid pass over all vertices has run (off_classic_routes).
  RecycledVector<struct ClosureNearVertexBuffer, std::pair<std::uint32_t, Point64>> near_vertex;
  bool near_vertex_complete = false;
};

// The polyline a segment is routed along: its ends, its exact split points and the centres of
// the hot pixels it meets, in order along it.
Ring route_of(const Segment& seg, std::vector<Point64> stops) {
  std::sort(stops.begin(), stops.end(), [&](Point64 x, Point64 y) {
    const Int128 px = projection(seg, x), py = projection(seg, y);
    return px != py ? px < py : x < y;
  });
  Ring r{seg.a};
  for (Point64 p : stops)
    if (p != r.back() && p != seg.b) r.push_back(p);
  r.push_back(seg.b);
  return r;
}

// Whether a query batch of `queries` against `segments` segments is better served by a grid
// walk along every segment than by box queries into the segment index.
bool many(std::size_t queries, std::size_t segments) { return queries > 64 && 8 * queries > segments; }

// The input segments near a point, found through a SegmentGrid of the input (find_contacts
// hands its own over on spiky inputs; otherwise it is built on first use). With many hot pixels
// or moved segments, asking at each point is far cheaper than walking every long segment
// through a grid of points: a point's cells hold a few dozen segments, while a spike crosses
// hundreds of point cells.
class SegmentsNear {
 public:
  explicit SegmentsNear(const std::vector<Segment>& segs) : segs_(segs) {}
  std::unique_ptr<SegmentGrid>& grid() { return grid_; }
  bool has_grid() const { return grid_ != nullptr; }
  // visit(s) once for every segment with a point within L-infinity distance 1 of p (and for
  // some farther ones: callers test exactly).
  template <class F>
  void for_each(Point64 p, F&& visit) {
    if (!grid_) grid_ = std::make_unique<SegmentGrid>(segs_);
    if (stamp_.empty() || token_ == kUnstamped - 1) {
      stamp_.assign(segs_.size(), kUnstamped);
      token_ = 0;
    }
    const std::uint32_t token = ++token_;
    grid_->for_each_in_box(Box64{{p.x - 1, p.y - 1}, {p.x + 1, p.y + 1}}, [&](std::uint32_t s) {
      if (stamp_[s] == token) return;
      stamp_[s] = token;
      visit(s);
    });
  }

 private:
  static constexpr std::uint32_t kUnstamped = 0xffffffffu;
  const std::vector<Segment>& segs_;
  std::unique_ptr<SegmentGrid> grid_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t token_ = 0;
};

// Grows the hot set until it is closed:
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
// Each round only looks at what is new. `fresh` holds the new hot centres on entry and is empty
// on return.
void close_hot_set(const std::vector<Segment>& segs, const SegmentIndex& index, SegmentsNear& near,
                   const std::vector<Point64>& split_points,
                   const StopsOf& splits_of, bool classic,
                   PointSet& is_hot, Closure& c, std::vector<Point64>& fresh) {
  std::vector<SweepBox> split_sweep;  // the split points' pixel boxes, sorted when first needed
  std::vector<std::uint32_t> slot;  // segment -> its place in `changed`, or kNoSlot
  constexpr std::uint32_t kNoSlot = 0xffffffffu;
  while (!fresh.empty()) {
    const std::uint32_t base = static_cast<std::uint32_t>(c.hot.size());
    c.hot.insert(c.hot.end(), fresh.begin(), fresh.end());
    RecycledVector<struct ChangedBuffer, std::uint32_t> changed;
    auto meet = [&](std::uint32_t h, std::uint32_t s) {
      const Point64 centre = fresh[h];
      if (!segment_meets_pixel(segs[s], centre)) return;
      c.meets.emplace_back(s, base + h);
      if (!on_segment(centre, segs[s])) c.moved[s] = true;
      changed.push_back(s);
    };
    if (near.has_grid() || many(fresh.size(), segs.size())) {
      // Many hot pixels (spiky inputs: long segments crossing everywhere, whose boxes cover
      // half the input), or a segment grid noding already built: each pixel asks the grid
      // for the segments through its cells.
      for (std::uint32_t h = 0; h < fresh.size(); ++h)
        near.for_each(fresh[h], [&](std::uint32_t s) { meet(h, s); });
    } else {
      index.query(pixel_boxes(fresh), meet);
    }
    fresh.clear();
    if (changed.size() > segs.size()) {  // many meetings: mark and list in order, no sort
      std::vector<bool> met_now(segs.size(), false);
      for (std::uint32_t s : changed) met_now[s] = true;
      changed.clear();
      for (std::uint32_t s = 0; s < segs.size(); ++s)
        if (met_now[s]) changed.push_back(s);
    } else {
      std::sort(changed.begin(), changed.end());
      changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
    }
    changed.erase(std::remove_if(changed.begin(), changed.end(),
                                 [&](std::uint32_t s) { return !c.moved[s]; }),
                  changed.end());
    if (changed.empty()) break;
    // Routes are built when first asked for: a vertex on the segment itself (its ends, its
    // split points) lies on the boundary of the region between segment and route, never
    // strictly inside, so on spiky inputs most moved segments never need theirs.
    std::unique_ptr<StopsOf> hot_stops;  // every hot centre met so far, by segment
    std::vector<Ring> routes(changed.size());
    auto route = [&](std::uint32_t k) -> const Ring& {
      if (routes[k].empty()) {
        if (!hot_stops) {
          std::vector<std::pair<std::uint32_t, Point64>> met;
          met.reserve(c.meets.size());
          for (const auto& [s, h] : c.meets) met.emplace_back(s, c.hot[h]);
          hot_stops = std::make_unique<StopsOf>(segs.size(), met);
        }
        std::vector<Point64> stops;
        hot_stops->append(changed[k], stops);
        splits_of.append(changed[k], stops);
        routes[k] = route_of(segs[changed[k]], std::move(stops));
      }
      return routes[k];
    };
    // Vertex p, whose closed pixel changed segment k meets (`on`: p lies on the segment):
    // pinned if the rule says so.
    auto pin_if_needed = [&](std::uint32_t k, Point64 p, bool on) {
      if ((!classic && on) || is_hot.contains(p)) return;
      const bool pin = classic ? segment_meets_pixel(segs[changed[k]], p)
                               : locate(p, route(k)) == PointLocation::kInside;
      if (!pin) return;
      is_hot.insert(p);
      fresh.push_back(p);
    };
    auto consider = [&](std::uint32_t k, Point64 p) {
      const Segment& seg = segs[changed[k]];
      if (segment_meets_closed_pixel(seg, p)) pin_if_needed(k, p, on_segment(p, seg));
    };
    if (many(changed.size(), segs.size())) {
      // Every vertex asks for the changed segments near it (a pass over all vertices: only
      // when the changed segments are many; a few are served by box queries below).
      slot.assign(segs.size(), kNoSlot);
      for (std::uint32_t k = 0; k < changed.size(); ++k) slot[changed[k]] = k;
      // The first such pass also records which segments pass near which vertices, for the
      // re-check (off_classic_routes), at the price of one more exact test per candidate.
      const bool record = !c.near_vertex_complete;
      auto at_vertex = [&](Point64 p) {
        near.for_each(p, [&](std::uint32_t s) {
          if ((slot[s] == kNoSlot && !record) || !segment_meets_closed_pixel(segs[s], p)) return;
          const bool on = on_segment(p, segs[s]);
          if (record && !on) c.near_vertex.emplace_back(s, p);
          if (slot[s] != kNoSlot) pin_if_needed(slot[s], p, on);
        });
      };
      for (const Segment& seg : segs) at_vertex(seg.a);  // every end starts a segment
      for (Point64 p : split_points) at_vertex(p);
      c.near_vertex_complete = true;
    } else {
      std::vector<Box64> boxes(changed.size());
      for (std::size_t k = 0; k < changed.size(); ++k) {
        const Box64 b = index.box(changed[k]);
        boxes[k] = {{b.min.x - 1, b.min.y - 1}, {b.max.x + 1, b.max.y + 1}};
      }
      index.query(boxes, [&](std::uint32_t k, std::uint32_t t) {
        consider(k, segs[t].a);
        consider(k, segs[t].b);
      });
      if (split_sweep.empty() && !split_points.empty())
        split_sweep = sorted_for_sweep(pixel_boxes(split_points));
      if (!split_sweep.empty())
        for_each_overlapping_pair(sorted_for_sweep(boxes), split_sweep,
                                  [&](std::uint32_t k, std::uint32_t v) { consider(k, split_points[v]); });
    }
    std::sort(fresh.begin(), fresh.end());  // deterministic order, independent of hashing
  }
}

// Routes every segment that has stops (split points, centres of hot pixels it meets) through
// them, in order along it. Segments without stops are their own fragment and are not listed.
Fragments route(const std::vector<Segment>& segs, const Closure& c,
                const std::vector<std::pair<std::uint32_t, Point64>>& splits) {
  RecycledVector<struct RouteStopsBuffer, std::pair<std::uint32_t, Point64>> stops;
  stops.assign(splits.begin(), splits.end());
  for (const auto& [s, h] : c.meets) stops.emplace_back(s, c.hot[h]);
  // By segment, then along each segment: most segments have one or two stops. With stops on
  // a good share of the segments (tiles: every edge cut once or twice) one counting pass over
  // segment ids beats the radix sort's two passes of 256 buckets.
  if (8 * stops.size() >= segs.size()) {
    counting_sort(stops, segs.size(), [](const auto& x) { return x.first; });
  } else {
    radix_sort(stops, [](const auto& x) { return std::uint64_t{x.first}; });
  }
  for (std::size_t i = 0; i < stops.size();) {
    std::size_t j = i + 1;
    while (j < stops.size() && stops[j].first == stops[i].first) ++j;
    if (j - i > 1) {
      const Segment& s = segs[stops[i].first];
      std::sort(stops.begin() + static_cast<std::ptrdiff_t>(i),
                stops.begin() + static_cast<std::ptrdiff_t>(j), [&](const auto& x, const auto& y) {
                  const Int128 px = projection(s, x.second), py = projection(s, y.second);
                  if (px != py) return px < py;
                  return x.second < y.second;
                });
    }
    i = j;
  }
  Fragments out;
  out.reserve(2 * stops.size());
  for (std::size_t k = 0; k < stops.size();) {
    const std::uint32_t s = stops[k].first;
    Point64 at = segs[s].a;
    for (; k < stops.size() && stops[k].first == s; ++k) {
      const Point64 p = stops[k].second;
      if (p == at || p == segs[s].b) continue;
      out.push_back({{at, p}, s});
      at = p;
    }
    out.push_back({{at, segs[s].b}, s});
  }
  return out;
}

// All fragments: the listed ones (ids 0 .. F-1) and, for every segment s without listed
// fragments, the segment itself (id F + s).
class AllFragments {
 public:
  AllFragments(const std::vector<Segment>& segs, const std::vector<Fragment>& listed)
      : segs_(segs), listed_(listed), first_(segs.size() + 1, 0) {
    for (const Fragment& f : listed) ++first_[f.parent + 1];
    for (std::size_t s = 0; s < segs.size(); ++s) first_[s + 1] += first_[s];
  }
  std::uint32_t listed_count() const { return static_cast<std::uint32_t>(listed_.size()); }
  std::uint32_t id_bound() const { return listed_count() + static_cast<std::uint32_t>(segs_.size()); }
  bool has_listed(std::uint32_t s) const { return first_[s] != first_[s + 1]; }
  const Segment& seg(std::uint32_t id) const {
    return id < listed_count() ? listed_[id].seg : segs_[id - listed_count()];
  }
  std::uint32_t parent(std::uint32_t id) const {
    return id < listed_count() ? listed_[id].parent : id - listed_count();
  }
  template <class F>
  void for_each_of(std::uint32_t s, F&& f) const {
    if (!has_listed(s)) return f(listed_count() + s);
    for (std::uint32_t g = first_[s]; g < first_[s + 1]; ++g) f(g);
  }
  // How many fragments there are in all.
  std::size_t count() const {
    std::size_t unlisted = 0;
    for (std::size_t s = 0; s < segs_.size(); ++s) unlisted += !has_listed(static_cast<std::uint32_t>(s));
    return listed_.size() + unlisted;
  }

 private:
  const std::vector<Segment>& segs_;
  const std::vector<Fragment>& listed_;
  std::vector<std::uint32_t> first_;
};

// Segments whose route may differ from the route classic snap rounding would give them if every
// vertex pixel were hot too: those meeting the closed pixel of a vertex that is neither hot nor on
// them. Every other segment's route is exactly that classic route: it already passes through
// its own ends and split points and through every hot pixel it meets (clip/README.md, "Which
// fragment pairs the re-check tests"). Read from the closure's record when it has a complete
// one (its vertices include every end and split point), found through `near` otherwise.
std::vector<bool> off_classic_routes(const std::vector<Segment>& segs, SegmentsNear& near,
                                     const std::vector<std::pair<std::uint32_t, Point64>>& splits,
                                     const PointSet& is_hot, const Closure& closure) {
  if (closure.near_vertex_complete) {
    std::vector<bool> off(segs.size(), false);
    for (const auto& [s, p] : closure.near_vertex)
      if (!is_hot.contains(p)) off[s] = true;
    return off;
  }
  std::vector<Point64> loose;  // vertices that are not hot
  loose.reserve(segs.size() + splits.size());
  for (const Segment& s : segs)
    if (!is_hot.contains(s.a)) loose.push_back(s.a);  // every end starts a segment
  for (const auto& sp : splits)
    if (!is_hot.contains(sp.second)) loose.push_back(sp.second);
  std::sort(loose.begin(), loose.end());
  loose.erase(std::unique(loose.begin(), loose.end()), loose.end());
  std::vector<bool> off(segs.size(), false);
  for (Point64 p : loose)
    near.for_each(p, [&](std::uint32_t s) {
      if (!off[s] && segment_meets_closed_pixel(segs[s], p) && !on_segment(p, segs[s])) off[s] = true;
    });
  return off;
}

// Contacts between fragments of moved segments and all fragments, each pair once. Split
// points are reported by fragment id (AllFragments). Pairs of two fragments on their classic
// routes are left out (README): off_classic() returns off_classic_routes, which is asked for
// on the grid path, and on the box path only when off_classic_is_known (the closure recorded
// it, so it costs no pass over all vertices).
template <class OffClassic>
Contacts recheck(const AllFragments& all, const std::vector<std::uint8_t>& moved,
                 const SegmentIndex& index, std::size_t segment_count, std::vector<std::uint8_t>& touched,
                 bool off_classic_is_known, OffClassic&& off_classic) {
  std::vector<std::uint32_t> which;
  which.reserve(all.listed_count());
  std::vector<bool> is_moved(all.listed_count(), false);  // moved segments are always listed
  for (std::uint32_t i = 0; i < all.listed_count(); ++i) {
    if (!moved[all.parent(i)]) continue;
    which.push_back(i);
    is_moved[i] = true;
  }
  auto moved_id = [&](std::uint32_t id) { return id < all.listed_count() && is_moved[id]; };
  Contacts c;
  auto check = [&](std::uint32_t f, std::uint32_t g) {
    if (classify_pair(all.seg(f), f, all.seg(g), g, c) != Meeting::kNone)
      touched[all.parent(f)] = touched[all.parent(g)] = true;
  };
  const std::size_t total = all.count();
  if (8 * which.size() < total && total < 2 * segment_count) {
    // Few moved fragments and few splits: query the segment index. Every fragment lies within
    // one unit of its segment's box (grow the query boxes by 2 to be safe). When the closure
    // already recorded which segments pass near which vertices, pairs on their classic routes
    // are left out as below (finding that out afresh would cost a pass over all vertices).
    std::vector<bool> off;
    if (off_classic_is_known) {
      // (Not reached by tests: no re-check with few moved fragments follows a closure that
      // recorded its near-vertex passes.)
      off = off_classic();
      if (std::find(off.begin(), off.end(), true) == off.end()) return c;
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    auto add = [&](std::uint32_t f, std::uint32_t g) {
      if (f == g || (moved_id(g) && g < f)) return;  // a moved pair is seen from both sides
      if (!off.empty() && !off[all.parent(f)] && !off[all.parent(g)]) return;
      pairs.emplace_back(std::min(f, g), std::max(f, g));
    };
    std::vector<Box64> boxes(which.size());
    for (std::size_t k = 0; k < which.size(); ++k) {
      const Box64 b = segment_box(all.seg(which[k]));
      boxes[k] = {{b.min.x - 2, b.min.y - 2}, {b.max.x + 2, b.max.y + 2}};
    }
    index.query(boxes, [&](std::uint32_t k, std::uint32_t s) {
      all.for_each_of(s, [&](std::uint32_t g) { add(which[k], g); });
    });
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    for (const auto& [f, g] : pairs) check(f, g);
  } else {
    // Many moved fragments (spiky inputs: cut short at every crossing). Only pairs with a
    // fragment off its classic route can meet other than at shared ends (README); every
    // fragment is walked through a grid (segment_grid.hpp), which proposes each pair once.
    const std::vector<bool> off = off_classic();
    if (std::find(off.begin(), off.end(), true) == off.end()) return c;
    std::vector<std::uint32_t> ids;
    std::vector<Segment> all_segments;
    ids.reserve(total);
    all_segments.reserve(total);
    for (std::uint32_t s = 0; s < segment_count; ++s)
      all.for_each_of(s, [&](std::uint32_t id) {
        ids.push_back(id);
        all_segments.push_back(all.seg(id));
      });
    SegmentGrid(all_segments).for_each_candidate_pair([&](std::uint32_t i, std::uint32_t j) {
      if ((moved_id(ids[i]) || moved_id(ids[j])) && (off[all.parent(ids[i])] || off[all.parent(ids[j])]) &&
          boxes_overlap(all_segments[i], all_segments[j]))
        check(ids[i], ids[j]);
    });
  }
  return c;
}

// The listed fragments after cutting fragments (by AllFragments id) at exact split points.
Fragments split_fragments(const AllFragments& all, std::size_t segment_count,
                                      const std::vector<std::pair<std::uint32_t, Point64>>& splits) {
  std::vector<Segment> pieces(all.id_bound());
  for (std::uint32_t id = 0; id < all.id_bound(); ++id) pieces[id] = all.seg(id);
  const Fragments cut = route(pieces, Closure{}, splits);  // by piece id
  std::vector<std::uint32_t> first(all.id_bound() + 1, 0);
  for (const Fragment& f : cut) ++first[f.parent + 1];
  for (std::size_t id = 0; id < all.id_bound(); ++id) first[id + 1] += first[id];
  Fragments out;
  for (std::uint32_t s = 0; s < segment_count; ++s)
    all.for_each_of(s, [&](std::uint32_t id) {
      if (first[id] == first[id + 1]) {
        if (id < all.listed_count()) out.push_back({all.seg(id), s});
        return;
      }
      for (std::uint32_t k = first[id]; k < first[id + 1]; ++k) out.push_back({cut[k].seg, s});
    });
  return out;
}

}  // namespace

Fragments snap_round(const std::vector<Segment>& segs, const std::vector<std::uint32_t>& next,
                     bool simple_rings, SnapStats& stats,
                     const std::vector<std::uint8_t>* screen_channel, std::size_t overlap_budget) {
  const SegmentIndex index(segs, next);
  stats.touched.assign(segs.size(), false);
  SegmentsNear near(segs);
  Contacts contacts = find_contacts(segs, next, index, simple_rings, stats.touched, &near.grid(),
                                    screen_channel, overlap_budget);
  stats.intersections = contacts.intersections;
  stats.operand_invalid = contacts.operand_invalid;
  stats.overlap_heavy = contacts.overlap_heavy;
  if (contacts.operand_invalid || contacts.overlap_heavy) return {};
  // The vertices below are every segment's start and every split point; an end that starts no
  // segment (an open run's: collinear_merge.hpp) joins them as a split point at the end, which
  // routing skips.
  for (std::uint32_t s = 0; s < segs.size(); ++s)
    if (segs[next[s]].a != segs[s].b) contacts.splits.emplace_back(s, segs[s].b);
  stats.moved_boxes.clear();
  // No crossing at a non-integer point: every contact is an exact split and nothing moves.
  if (contacts.hot.empty()) return route(segs, Closure{}, contacts.splits);

  // Vertex pixels: the segments' endpoints (found through the index) and exact split points.
  RecycledVector<struct SplitPointsBuffer, Point64> split_points;
  split_points.reserve(contacts.splits.size());
  for (const auto& sp : contacts.splits) split_points.push_back(sp.second);

  PointSet is_hot;
  is_hot.reserve(2 * contacts.hot.size());
  Closure closure;
  closure.moved.assign(segs.size(), false);
  RecycledVector<struct FreshBuffer, Point64> fresh;
  auto add_hot = [&](const std::vector<Point64>& pts) {
    for (Point64 p : pts)
      if (is_hot.insert(p)) fresh.push_back(p);
  };
  add_hot(contacts.hot);

  const StopsOf splits_of(segs.size(), contacts.splits);

  // The stable rule normally converges in one round. Should crossings survive it a few times,
  // switch to the classic closure, for which snap rounding's theorem rules them out.
  constexpr std::size_t kStableRounds = 4, kMaxRounds = 16;
  for (std::size_t round = 1;; ++round) {
    const bool classic = round > kStableRounds;
    if (round == kStableRounds + 1) {
      // Re-run the whole closure under the classic rule from the hot pixels found so far. (Not
      // reached by tests: the stable rule converges within 4 rounds on every test input.)
      fresh.insert(fresh.end(), closure.hot.begin(), closure.hot.end());
      std::sort(fresh.begin(), fresh.end());
      fresh.erase(std::unique(fresh.begin(), fresh.end()), fresh.end());
      closure = Closure{};
      closure.moved.assign(segs.size(), false);
      is_hot.clear();
      for (Point64 p : fresh) is_hot.insert(p);
    }
    std::sort(fresh.begin(), fresh.end());
    std::sort(split_points.begin(), split_points.end());
    split_points.erase(std::unique(split_points.begin(), split_points.end()), split_points.end());
    close_hot_set(segs, index, near, split_points, splits_of, classic, is_hot, closure, fresh);
    fresh.clear();
    for (const auto& m : closure.meets) stats.touched[m.first] = true;
    Fragments frags = route(segs, closure, contacts.splits);
    stats.hot_pixels = closure.hot.size();
    stats.moved_boxes.clear();
    stats.moved_boxes.reserve(static_cast<std::size_t>(
        std::count(closure.moved.begin(), closure.moved.end(), true)));
    for (std::uint32_t i = 0; i < segs.size(); ++i)
      if (closure.moved[i]) stats.moved_boxes.push_back(index.box(i));

    // Safety re-check: fragments of moved segments against everything they may meet that the
    // snap-rounding theorem does not already cover, exactly.
    const AllFragments all(segs, frags);
    Contacts again = recheck(all, closure.moved, index, segs.size(), stats.touched,
                             closure.near_vertex_complete,
                             [&] { return off_classic_routes(segs, near, contacts.splits, is_hot, closure); });
    if (again.hot.empty()) {
      if (again.splits.empty()) return frags;
      // Only exact integer splits remain (snapped fragments landing on vertices or overlapping
      // collinearly): split and finish; nothing moves.
      return split_fragments(all, segs.size(), again.splits);
    }
    // A crossing survived: snap rounding's guarantee was violated; make its pixel hot and
    // run the closure again over the original segments.
    // Not reached by tests: the stable rule converges within kStableRounds rounds on every test
    // input; the limit is a defensive stop.
    if (round >= kMaxRounds) throw std::logic_error("snap rounding did not converge");
    add_hot(again.hot);
    for (const auto& sp : again.splits) split_points.push_back(sp.second);
  }
}

}  // namespace edgeland::detail
