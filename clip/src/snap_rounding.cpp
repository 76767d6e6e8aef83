#include "snap_rounding.hpp"

#include <algorithm>
#include <stdexcept>
#include <unordered_set>
#include <utility>

#include "box_sweep.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/pixel.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "noding.hpp"

namespace edgeland::detail {
namespace {

using PointSet = std::unordered_set<Point64, Point64Hash>;

// A box that contains the whole pixel of p (closed, integer corners).
Box64 pixel_box(Point64 p) { return Box64{{p.x - 1, p.y - 1}, {p.x + 1, p.y + 1}}; }

std::vector<Box64> pixel_boxes(const std::vector<Point64>& pts) {
  std::vector<Box64> boxes(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) boxes[i] = pixel_box(pts[i]);
  return boxes;
}

struct Closure {
  std::vector<Point64> hot;                                      // all hot pixel centres
  std::vector<std::pair<std::uint32_t, std::uint32_t>> meets;    // (segment, hot index)
  std::vector<bool> moved;
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

// Grows the hot set until it is closed:
//  * every segment meeting a hot pixel off its centre is moved (routed through the centre);
//  * stable rule: a vertex becomes hot when the route of a moved segment would jump over it,
//    i.e. it lies strictly inside the region between the segment and its route (the closed
//    polyline route + segment winds around it). Only such a vertex could end up on the other
//    side of the snapped segment; vertices merely near the segment are left alone, which is
//    what keeps far edges unchanged (locality);
//  * classic rule (fallback): every vertex pixel a moved segment meets becomes hot, as in
//    Guibas-Marimont snap rounding, whose theorem guarantees no new crossing.
// Each round only looks at what is new.
void close_hot_set(const std::vector<Segment>& segs, const std::vector<SweepBox>& seg_sweep,
                   const std::vector<Point64>& vertices, const std::vector<SweepBox>& vertex_sweep,
                   const std::vector<std::vector<Point64>>& splits_of, bool classic,
                   PointSet& is_hot, Closure& c, std::vector<Point64> fresh) {
  std::vector<std::vector<Point64>> hot_stops(segs.size());
  for (const auto& [s, h] : c.meets) hot_stops[s].push_back(c.hot[h]);
  while (!fresh.empty()) {
    const std::uint32_t base = static_cast<std::uint32_t>(c.hot.size());
    c.hot.insert(c.hot.end(), fresh.begin(), fresh.end());
    std::vector<std::uint32_t> changed;
    for_each_overlapping_pair(sorted_for_sweep(pixel_boxes(fresh)), seg_sweep,
                              [&](std::uint32_t h, std::uint32_t s) {
                                const Point64 centre = fresh[h];
                                if (!segment_meets_pixel(segs[s], centre)) return;
                                c.meets.emplace_back(s, base + h);
                                hot_stops[s].push_back(centre);
                                if (!on_segment(centre, segs[s])) c.moved[s] = true;
                                changed.push_back(s);
                              });
    fresh.clear();
    std::sort(changed.begin(), changed.end());
    changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
    changed.erase(std::remove_if(changed.begin(), changed.end(),
                                 [&](std::uint32_t s) { return !c.moved[s]; }),
                  changed.end());
    if (changed.empty()) break;
    std::vector<Box64> boxes(changed.size());
    std::vector<Ring> routes(changed.size());
    for (std::size_t k = 0; k < changed.size(); ++k) {
      const std::uint32_t s = changed[k];
      boxes[k] = segment_box(segs[s]);
      if (!classic) {
        std::vector<Point64> stops = hot_stops[s];
        stops.insert(stops.end(), splits_of[s].begin(), splits_of[s].end());
        routes[k] = route_of(segs[s], std::move(stops));
      }
    }
    for_each_overlapping_pair(sorted_for_sweep(boxes), vertex_sweep,
                              [&](std::uint32_t k, std::uint32_t v) {
                                const Point64 p = vertices[v];
                                if (is_hot.count(p)) return;
                                const bool pin =
                                    classic ? segment_meets_pixel(segs[changed[k]], p)
                                            : locate(p, routes[k]) == PointLocation::kInside;
                                if (!pin) return;
                                is_hot.insert(p);
                                fresh.push_back(p);
                              });
    std::sort(fresh.begin(), fresh.end());  // deterministic order, independent of hashing
  }
}

// Routes every segment through its split points and the centres of the hot pixels it meets.
std::vector<Fragment> route(const std::vector<Segment>& segs, const Closure& c,
                            const std::vector<std::pair<std::uint32_t, Point64>>& splits) {
  std::vector<std::pair<std::uint32_t, Point64>> stops = splits;
  for (const auto& [s, h] : c.meets) stops.emplace_back(s, c.hot[h]);
  std::sort(stops.begin(), stops.end(), [&](const auto& x, const auto& y) {
    if (x.first != y.first) return x.first < y.first;
    const Segment& s = segs[x.first];
    const Int128 px = projection(s, x.second), py = projection(s, y.second);
    if (px != py) return px < py;
    return x.second < y.second;
  });
  std::vector<Fragment> out;
  out.reserve(segs.size() + stops.size());
  std::size_t k = 0;
  for (std::uint32_t s = 0; s < segs.size(); ++s) {
    Point64 at = segs[s].a;
    for (; k < stops.size() && stops[k].first == s; ++k) {
      const Point64 p = stops[k].second;
      if (p == at || p == segs[s].b) continue;
      out.push_back({{at, p}, s});
      at = p;
    }
    if (at != segs[s].b) out.push_back({{at, segs[s].b}, s});
  }
  return out;
}

// Contacts between fragments of moved segments and all fragments, each pair once.
Contacts recheck(const std::vector<Fragment>& frags, const std::vector<bool>& moved,
                 std::size_t segment_count, const std::vector<SweepBox>& seg_sweep) {
  std::vector<Box64> boxes;
  std::vector<std::uint32_t> which;
  std::vector<bool> is_moved(frags.size(), false);
  for (std::uint32_t i = 0; i < frags.size(); ++i) {
    if (!moved[frags[i].parent]) continue;
    boxes.push_back(segment_box(frags[i].seg));
    which.push_back(i);
    is_moved[i] = true;
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  auto add = [&](std::uint32_t f, std::uint32_t g) {
    if (f == g || (is_moved[g] && g < f)) return;  // a moved pair is seen from both sides
    pairs.emplace_back(std::min(f, g), std::max(f, g));
  };
  if (8 * which.size() < frags.size() && frags.size() < 2 * segment_count) {
    // Few moved fragments and few splits: reuse the segments' sweep order. Every fragment lies
    // within one unit of its segment's box (grow the query boxes by 2 to be safe).
    std::vector<std::uint32_t> first(segment_count + 1, 0);
    for (const Fragment& f : frags) ++first[f.parent + 1];
    for (std::size_t s = 0; s < segment_count; ++s) first[s + 1] += first[s];
    for (Box64& b : boxes) b = {{b.min.x - 2, b.min.y - 2}, {b.max.x + 2, b.max.y + 2}};
    for_each_overlapping_pair(sorted_for_sweep(boxes), seg_sweep, [&](std::uint32_t k, std::uint32_t s) {
      for (std::uint32_t g = first[s]; g < first[s + 1]; ++g) add(which[k], g);
    });
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  } else {
    std::vector<Box64> all(frags.size());
    for (std::size_t i = 0; i < frags.size(); ++i) all[i] = segment_box(frags[i].seg);
    for_each_overlapping_pair(sorted_for_sweep(boxes), sorted_for_sweep(all),
                              [&](std::uint32_t k, std::uint32_t g) { add(which[k], g); });
  }
  Contacts c;
  for (const auto& [f, g] : pairs) classify_pair(frags[f].seg, f, frags[g].seg, g, c);
  return c;
}

// Pixel boxes of points already in lexicographic (hence min-x) order.
std::vector<SweepBox> sweep_of_sorted_points(const std::vector<Point64>& pts) {
  std::vector<SweepBox> s(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    s[i] = {pts[i].x - 1, pts[i].x + 1, pts[i].y - 1, pts[i].y + 1, static_cast<std::uint32_t>(i)};
  return s;
}

}  // namespace

std::vector<Fragment> snap_round(const std::vector<Segment>& segs, SnapStats& stats) {
  std::vector<Box64> seg_boxes(segs.size());
  for (std::size_t i = 0; i < segs.size(); ++i) seg_boxes[i] = segment_box(segs[i]);
  const std::vector<SweepBox> seg_sweep = sorted_for_sweep(seg_boxes);
  Contacts contacts = find_contacts(segs, seg_sweep);
  stats.intersections = contacts.intersections;
  stats.moved_boxes.clear();
  // No crossing at a non-integer point: every contact is an exact split and nothing moves.
  if (contacts.hot.empty()) return route(segs, Closure{}, contacts.splits);

  // Vertex pixels: input endpoints and exact split points.
  std::vector<Point64> vertices;
  vertices.reserve(2 * segs.size() + contacts.splits.size());
  for (const Segment& s : segs) {
    vertices.push_back(s.a);
    vertices.push_back(s.b);
  }
  for (const auto& sp : contacts.splits) vertices.push_back(sp.second);

  PointSet is_hot;
  Closure closure;
  closure.moved.assign(segs.size(), false);
  std::vector<Point64> fresh;
  auto add_hot = [&](const std::vector<Point64>& pts) {
    for (Point64 p : pts)
      if (is_hot.insert(p).second) fresh.push_back(p);
  };
  add_hot(contacts.hot);

  std::vector<std::vector<Point64>> splits_of(segs.size());
  for (const auto& [s, p] : contacts.splits) splits_of[s].push_back(p);

  // The stable rule normally converges in one round. Should crossings survive it a few times,
  // switch to the classic closure, for which snap rounding's theorem rules them out.
  constexpr std::size_t kStableRounds = 4, kMaxRounds = 16;
  for (std::size_t round = 1;; ++round) {
    const bool classic = round > kStableRounds;
    if (round == kStableRounds + 1) {
      // Re-run the whole closure under the classic rule from the hot pixels found so far.
      fresh.insert(fresh.end(), closure.hot.begin(), closure.hot.end());
      std::sort(fresh.begin(), fresh.end());
      fresh.erase(std::unique(fresh.begin(), fresh.end()), fresh.end());
      closure = Closure{};
      closure.moved.assign(segs.size(), false);
      is_hot.clear();
      is_hot.insert(fresh.begin(), fresh.end());
    }
    std::sort(fresh.begin(), fresh.end());
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    close_hot_set(segs, seg_sweep, vertices, sweep_of_sorted_points(vertices), splits_of, classic,
                  is_hot, closure, std::move(fresh));
    fresh.clear();
    std::vector<Fragment> frags = route(segs, closure, contacts.splits);
    stats.rounds = round;
    stats.hot_pixels = closure.hot.size();
    stats.moved_boxes.clear();
    for (std::size_t i = 0; i < segs.size(); ++i)
      if (closure.moved[i]) stats.moved_boxes.push_back(seg_boxes[i]);

    // Safety re-check: fragments of moved segments against everything, exactly.
    Contacts again = recheck(frags, closure.moved, segs.size(), seg_sweep);
    if (again.hot.empty()) {
      if (again.splits.empty()) return frags;
      // Only exact integer splits remain (snapped fragments landing on vertices or overlapping
      // collinearly): split and finish; nothing moves.
      std::vector<Segment> pieces(frags.size());
      for (std::size_t i = 0; i < frags.size(); ++i) pieces[i] = frags[i].seg;
      std::vector<Fragment> out;
      std::vector<Fragment> split = route(pieces, Closure{}, again.splits);
      out.reserve(split.size());
      for (const Fragment& f : split) out.push_back({f.seg, frags[f.parent].parent});
      return out;
    }
    // A crossing survived: snap rounding's guarantee was violated; make its pixel hot and
    // run the closure again over the original segments.
    if (round >= kMaxRounds) throw std::logic_error("snap rounding did not converge");
    add_hot(again.hot);
    for (const auto& sp : again.splits) vertices.push_back(sp.second);
  }
}

}  // namespace edgeland::detail
