// Snap rounding of a small edge list (small_overlay.hpp): snap_round()'s rules (clip/README.md,
// "Snap rounding") with every search a scan. The closure runs in snap_closure.cpp's rounds: each
// round meets the fresh hot pixels, keeps the segments they moved, and pins every vertex the
// route of such a segment (through every hot centre it met so far and its split points) would
// jump over; the routes are then cut, and the moved fragments re-checked against every fragment.
// The rounds, the rule and the route of each segment are snap_round()'s, so the hot set and the
// fragments are too; only the order of the scans differs, and nothing depends on it (hot centres
// and pins are sets, stops are sorted along their segment).
#include <algorithm>
#include <utility>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/pixel.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "grown_box.hpp"
#include "point_set.hpp"
#include "small_overlay.hpp"

namespace edgeland::detail {
namespace {

using SegmentPoint = std::pair<std::uint32_t, Point64>;

// More hot pixels than a cell's overlay has (it has a handful): the general snap_round() takes
// those, whose searches pay off.
constexpr std::size_t kSmallHotPixels = 64;

// One per thread, kept between calls: the steady state allocates nothing.
struct SnapWork {
  std::vector<Box64> box;         // per segment
  std::vector<Point64> vertices;  // every segment start and every split point
  std::vector<Point64> hot;       // hot centres, in the order they became hot
  std::vector<std::pair<std::uint32_t, std::uint32_t>> meets;  // (segment, hot index)
  std::vector<std::uint8_t> moved;                             // by segment
  std::vector<Point64> fresh;                                  // hot centres not closed over yet
  std::vector<std::uint32_t> changed;  // segments moved by this round's fresh pixels
  std::vector<SegmentPoint> stops;     // routing: (segment, stop)
  std::vector<std::pair<std::uint32_t, Box64>> moved_fragments;  // re-check: (id, box)
  std::vector<Point64> route_stops;
  Ring route;
  PointSet is_hot;
};

SnapWork& snap_work() {
  thread_local SnapWork w;
  return w;
}

// The stops of one segment in order along it (then by point, as snap_round() sorts them).
void sort_along(const Segment& seg, SegmentPoint* first, SegmentPoint* last) {
  std::sort(first, last, [&](const SegmentPoint& x, const SegmentPoint& y) {
    const Int128 px = projection(seg, x.second), py = projection(seg, y.second);
    return px != py ? px < py : x.second < y.second;
  });
}

// Appends the fragments of every segment with stops, cut at them in order (snap_steps::route:
// a stop at the fragment's start or at the segment's end cuts nothing), segments in order.
// `stops` is sorted here.
void cut_at_stops(const std::vector<Segment>& segs, std::vector<SegmentPoint>& stops,
                  std::vector<Fragment>& out) {
  std::sort(stops.begin(), stops.end(),
            [](const SegmentPoint& x, const SegmentPoint& y) { return x.first < y.first; });
  for (std::size_t k = 0; k < stops.size();) {
    const std::uint32_t s = stops[k].first;
    std::size_t end = k;
    while (end < stops.size() && stops[end].first == s) ++end;
    sort_along(segs[s], stops.data() + k, stops.data() + end);
    Point64 at = segs[s].a;
    for (; k < end; ++k) {
      const Point64 p = stops[k].second;
      if (p == at || p == segs[s].b) continue;
      out.push_back({{at, p}, s});
      at = p;
    }
    out.push_back({{at, segs[s].b}, s});
  }
}

// The stable closure (snap_closure.cpp's HotSetClosure, every search a scan).
class SmallClosure {
 public:
  SmallClosure(const std::vector<Segment>& segs, const Contacts& contacts, SnapWork& w)
      : segs_(segs), contacts_(contacts), w_(w) {}

  void run() {
    while (!w_.fresh.empty()) {
      meet_fresh();
      if (w_.changed.empty()) break;
      pin_jumped_vertices();
      std::sort(w_.fresh.begin(), w_.fresh.end());
    }
  }

 private:
  // The fresh pixels join the hot set; changed: the moved segments meeting one, each once.
  void meet_fresh() {
    const auto base = static_cast<std::uint32_t>(w_.hot.size());
    w_.hot.insert(w_.hot.end(), w_.fresh.begin(), w_.fresh.end());
    w_.changed.clear();
    for (std::uint32_t h = 0; h < w_.fresh.size(); ++h) {
      const Point64 centre = w_.fresh[h];
      const Box64 pixel = pixel_box(centre);
      for (std::uint32_t s = 0; s < segs_.size(); ++s) {
        if (!w_.box[s].overlaps(pixel) || !segment_meets_pixel(segs_[s], centre)) continue;
        w_.meets.emplace_back(s, base + h);
        if (!on_segment(centre, segs_[s])) w_.moved[s] = true;
        w_.changed.push_back(s);
      }
    }
    w_.fresh.clear();
    std::sort(w_.changed.begin(), w_.changed.end());
    w_.changed.erase(std::unique(w_.changed.begin(), w_.changed.end()), w_.changed.end());
    w_.changed.erase(std::remove_if(w_.changed.begin(), w_.changed.end(),
                                    [&](std::uint32_t s) { return !w_.moved[s]; }),
                     w_.changed.end());
  }

  // Every vertex a changed segment's route would jump over becomes hot (fresh).
  void pin_jumped_vertices() {
    for (std::uint32_t s : w_.changed) {
      const Box64 reach = grown(w_.box[s], 1);
      bool routed = false;
      for (Point64 p : w_.vertices) {
        if (!reach.contains(p) || !segment_meets_closed_pixel(segs_[s], p)) continue;
        if (on_segment(p, segs_[s]) || w_.is_hot.contains(p)) continue;
        if (!routed) route_of(s);
        routed = true;
        if (locate(p, w_.route) != PointLocation::kInside) continue;
        w_.is_hot.insert(p);
        w_.fresh.push_back(p);
      }
    }
  }

  // w_.route: segment s through its split points and every hot centre it met so far.
  void route_of(std::uint32_t s) {
    w_.stops.clear();
    for (const auto& [t, h] : w_.meets)
      if (t == s) w_.stops.emplace_back(s, w_.hot[h]);
    for (const auto& sp : contacts_.splits)
      if (sp.first == s) w_.stops.push_back(sp);
    sort_along(segs_[s], w_.stops.data(), w_.stops.data() + w_.stops.size());
    w_.route.assign(1, segs_[s].a);
    for (const auto& st : w_.stops)
      if (st.second != w_.route.back() && st.second != segs_[s].b) w_.route.push_back(st.second);
    w_.route.push_back(segs_[s].b);
  }

  const std::vector<Segment>& segs_;
  const Contacts& contacts_;
  SnapWork& w_;
};

// All fragments of the re-check: listed ones (ids 0 .. F-1) and every segment without listed
// fragments (id F + s), as snap_recheck.cpp numbers them.
struct FragmentIds {
  const std::vector<Segment>& segs;
  const std::vector<Fragment>& listed;
  const std::vector<std::uint8_t>& has_listed;  // by segment
  std::uint32_t count() const { return static_cast<std::uint32_t>(listed.size() + segs.size()); }
  bool exists(std::uint32_t id) const {
    return id < listed.size() || !has_listed[id - listed.size()];
  }
  const Segment& seg(std::uint32_t id) const {
    return id < listed.size() ? listed[id].seg : segs[id - listed.size()];
  }
  std::uint32_t parent(std::uint32_t id) const {
    return id < listed.size() ? listed[id].parent : id - static_cast<std::uint32_t>(listed.size());
  }
};

// Every moved fragment against every fragment whose box meets its own (each pair once), exactly:
// what it finds goes to `found`, and both fragments' segments are touched. (snap_recheck.cpp
// leaves out pairs of two fragments on their classic routes, which cannot cross nor hold a
// vertex inside either; finding those routes costs more than the few pairs here.) One pass over
// the fragments, each compared with the moved ones only when it meets their common box.
void recheck_moved(const FragmentIds& all, const std::vector<std::uint8_t>& moved,
                   std::vector<std::uint8_t>& touched, SnapWork& w, Contacts& found) {
  auto is_moved = [&](std::uint32_t id) { return id < all.listed.size() && moved[all.parent(id)]; };
  w.moved_fragments.clear();
  Box64 reach{};
  for (std::uint32_t f = 0; f < all.listed.size(); ++f) {
    if (!is_moved(f)) continue;
    const Box64 b = segment_box(all.seg(f));
    if (w.moved_fragments.empty()) reach = b;
    reach.expand(b);
    w.moved_fragments.push_back({f, b});
  }
  for (std::uint32_t g = 0; g < all.count(); ++g) {
    if (!all.exists(g)) continue;
    const Box64 gb = segment_box(all.seg(g));
    if (!gb.overlaps(reach)) continue;
    const bool g_moved = is_moved(g);
    for (const auto& [f, fb] : w.moved_fragments) {
      if (g == f || (g_moved && g < f) || !fb.overlaps(gb)) continue;
      if (classify_pair(all.seg(f), f, all.seg(g), g, found) != Meeting::kNone)
        touched[all.parent(f)] = touched[all.parent(g)] = true;
    }
  }
}

// The fragments cut at the re-check's exact split points (by fragment id), segments in order,
// as snap_recheck.cpp's split_fragments lists them: a segment without listed fragments that is
// cut becomes listed.
void split_fragments(const FragmentIds& all, std::vector<SegmentPoint>& splits, Fragments& out) {
  std::sort(splits.begin(), splits.end(),
            [](const SegmentPoint& x, const SegmentPoint& y) { return x.first < y.first; });
  Fragments result;
  auto emit = [&](std::uint32_t id, std::uint32_t s) {
    const Segment& seg = all.seg(id);
    auto k = std::lower_bound(splits.begin(), splits.end(), id,
                              [](const SegmentPoint& x, std::uint32_t i) { return x.first < i; });
    auto end = k;
    while (end != splits.end() && end->first == id) ++end;
    if (k == end) {
      if (id < all.listed.size()) result.push_back({seg, s});
      return;
    }
    sort_along(seg, &*k, &*k + (end - k));
    Point64 at = seg.a;
    for (; k != end; ++k) {
      if (k->second == at || k->second == seg.b) continue;
      result.push_back({{at, k->second}, s});
      at = k->second;
    }
    result.push_back({{at, seg.b}, s});
  };
  std::uint32_t f = 0;
  for (std::uint32_t s = 0; s < all.segs.size(); ++s) {
    if (!all.has_listed[s]) {
      emit(static_cast<std::uint32_t>(all.listed.size()) + s, s);
      continue;
    }
    for (; f < all.listed.size() && all.listed[f].parent == s; ++f) emit(f, s);
  }
  out.swap(result);
}

// The closure's state from the contacts: the vertices, the first hot pixels (fresh, sorted).
void start_closure(const std::vector<Segment>& segs, const Contacts& contacts, SnapWork& w) {
  const std::size_t n = segs.size();
  w.box.resize(n);
  w.vertices.clear();
  for (std::size_t s = 0; s < n; ++s) {
    w.box[s] = segment_box(segs[s]);
    w.vertices.push_back(segs[s].a);  // every end starts a segment (closed rings)
  }
  for (const auto& sp : contacts.splits) w.vertices.push_back(sp.second);
  w.hot.clear();
  w.meets.clear();
  w.moved.assign(n, false);
  w.fresh.clear();
  w.is_hot.clear();
  for (Point64 p : contacts.hot)
    if (w.is_hot.insert(p)) w.fresh.push_back(p);
  std::sort(w.fresh.begin(), w.fresh.end());
}

// The routed fragments: every segment cut at its split points and the hot centres it meets.
void route_all(const std::vector<Segment>& segs, const Contacts& contacts, SnapWork& w,
               Fragments& out) {
  w.stops.assign(contacts.splits.begin(), contacts.splits.end());
  for (const auto& [s, h] : w.meets) w.stops.emplace_back(s, w.hot[h]);
  out.clear();
  cut_at_stops(segs, w.stops, out);
}

// The re-check of the routed fragments; false if a crossing survived.
bool recheck(const std::vector<Segment>& segs, SnapWork& w, Snapped& out) {
  ScratchVector<std::uint8_t> has_listed;
  has_listed.assign(segs.size(), false);
  for (const Fragment& f : out.fragments) has_listed[f.parent] = true;
  const FragmentIds all{segs, out.fragments, has_listed};
  Contacts found;
  recheck_moved(all, w.moved, out.touched, w, found);
  if (!found.hot.empty()) return false;
  if (!found.splits.empty()) split_fragments(all, found.splits, out.fragments);
  return true;
}

}  // namespace

bool snap_round_small(const EdgeList& edges, Contacts& contacts, Snapped& out) {
  const std::vector<Segment>& segs = edges.segments;
  if (contacts.hot.size() > kSmallHotPixels) return false;
  SnapWork& w = snap_work();
  out.touched.swap(contacts.touched);
  out.moved_boxes.clear();
  out.hot_pixels = 0;
  if (contacts.hot.empty()) {  // every contact an exact split: nothing moves
    w.meets.clear();
    route_all(segs, contacts, w, out.fragments);
    return true;
  }
  start_closure(segs, contacts, w);
  SmallClosure(segs, contacts, w).run();
  for (const auto& m : w.meets) out.touched[m.first] = true;
  out.hot_pixels = w.hot.size();
  for (std::uint32_t s = 0; s < segs.size(); ++s)
    if (w.moved[s]) out.moved_boxes.push_back(w.box[s]);
  route_all(segs, contacts, w, out.fragments);
  return recheck(segs, w, out);
}

}  // namespace edgeland::detail
