// Snap rounding (snap_rounding.hpp): the rounds of closing the hot set, routing and
// re-checking (snap_rounding_steps.hpp), until the re-check finds no crossing.
#include "snap_rounding.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/pixel.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "offsets.hpp"
#include "radix_sort.hpp"
#include "snap_rounding_steps.hpp"

namespace edgeland::detail {
namespace snap_steps {

StopsOf::StopsOf(std::size_t segments, const std::vector<SegmentPoint>& stops) {
  begin_.assign(segments + 1, 0);
  points_.resize(stops.size());
  for (const auto& st : stops) ++begin_[st.first + 1];
  add_up_counts(begin_);
  ScratchVector<std::uint32_t> fill;
  fill.assign(begin_.begin(), begin_.end() - 1);
  for (const auto& [s, p] : stops) points_[fill[s]++] = p;
}

namespace {

// Stops by segment, then along each segment: most segments have one or two stops. With stops
// on a good share of the segments (tiles: every edge cut once or twice) one counting pass over
// segment ids beats the radix sort's two passes of 256 buckets.
template <class Stops>
void sort_stops(const std::vector<Segment>& segs, Stops& stops) {
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
}

}  // namespace

Fragments route(const std::vector<Segment>& segs, const Closure& c,
                const std::vector<SegmentPoint>& splits) {
  ScratchVector<SegmentPoint> stops;
  stops.assign(splits.begin(), splits.end());
  for (const auto& [s, h] : c.meets) stops.emplace_back(s, c.hot[h]);
  sort_stops(segs, stops);
  // One fragment per stop and one more per segment with stops: reserved exactly (twice the
  // stops was 160 MB too many at 10^6-vertex combs).
  std::size_t segments_with_stops = 0;
  for (std::size_t k = 0; k < stops.size(); ++k)
    segments_with_stops += k == 0 || stops[k].first != stops[k - 1].first;
  Fragments out;
  out.reserve(stops.size() + segments_with_stops);
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

namespace {

// The rounds of snap rounding over segments whose exact contacts found non-integer crossings.
// The stable rule normally converges in one round. Should crossings survive it a few times,
// the closure is run again under the classic rule, for which snap rounding's theorem rules
// them out.
class SnapRounds {
 public:
  static constexpr std::size_t kStableRounds = 4, kMaxRounds = 16;

  SnapRounds(const std::vector<Segment>& segs, const Contacts& contacts, SegmentSearch& search)
      : segs_(segs),
        contacts_(contacts),
        search_(search),
        splits_of_(segs.size(), contacts.splits) {
    split_points_.reserve(contacts.splits.size());
    for (const auto& sp : contacts.splits) split_points_.push_back(sp.second);
    is_hot_.reserve(2 * contacts.hot.size());
    closure_.moved.assign(segs.size(), false);
    add_hot(contacts.hot);
  }

  void run(Snapped& out) {
    for (std::size_t round = 1;; ++round) {
      if (round == kStableRounds + 1) restart_classic();
      close(round > kStableRounds, out);
      // The re-check reads the closure's record of which segments pass near which vertices
      // instead of asking the grid; only another round would (clip/README.md, "Snap rounding").
      if (closure_.near_vertex_complete) search_.near.release_grid();
      snap_steps::Rechecked again =
          recheck(segs_, route(segs_, closure_, contacts_.splits), closure_, search_,
                  contacts_.splits, is_hot_, out.touched);
      if (again.found.hot.empty()) {
        out.fragments.swap(again.fragments);
        return;
      }
      // A crossing survived: snap rounding's guarantee was violated; make its pixel hot and
      // run the closure again over the original segments. Not reached by tests: the stable
      // rule converges within kStableRounds rounds on every test input; the limit is a
      // defensive stop.
      if (round >= kMaxRounds) fail_stage("snap rounding", "did not converge");
      add_hot(again.found.hot);
      for (const auto& sp : again.found.splits) split_points_.push_back(sp.second);
    }
  }

 private:
  void add_hot(const std::vector<Point64>& pts) {
    for (Point64 p : pts)
      if (is_hot_.insert(p)) fresh_.push_back(p);
  }

  // Re-runs the whole closure under the classic rule from the hot pixels found so far. (Not
  // reached by tests: the stable rule converges within 4 rounds on every test input.)
  void restart_classic() {
    fresh_.insert(fresh_.end(), closure_.hot.begin(), closure_.hot.end());
    std::sort(fresh_.begin(), fresh_.end());
    fresh_.erase(std::unique(fresh_.begin(), fresh_.end()), fresh_.end());
    closure_ = Closure{};
    closure_.moved.assign(segs_.size(), false);
    is_hot_.clear();
    for (Point64 p : fresh_) is_hot_.insert(p);
  }

  // One closure, and what it tells the plane graph: touched segments, moved boxes, hot pixels.
  void close(bool classic, Snapped& out) {
    std::sort(fresh_.begin(), fresh_.end());
    std::sort(split_points_.begin(), split_points_.end());
    split_points_.erase(std::unique(split_points_.begin(), split_points_.end()),
                        split_points_.end());
    close_hot_set({segs_, search_, split_points_, splits_of_}, classic, is_hot_, closure_, fresh_);
    fresh_.clear();
    for (const auto& m : closure_.meets) out.touched[m.first] = true;
    out.hot_pixels = closure_.hot.size();
    out.moved_boxes.clear();
    out.moved_boxes.reserve(
        static_cast<std::size_t>(std::count(closure_.moved.begin(), closure_.moved.end(), true)));
    for (std::uint32_t i = 0; i < segs_.size(); ++i)
      if (closure_.moved[i]) out.moved_boxes.push_back(search_.index.box(i));
  }

  const std::vector<Segment>& segs_;
  const Contacts& contacts_;
  SegmentSearch& search_;
  const StopsOf splits_of_;
  // The vertices: every segment's start (found through the index) and every split point.
  ScratchVector<Point64> split_points_;
  PointSet is_hot_;
  Closure closure_;
  ScratchVector<Point64> fresh_;  // hot centres not yet closed over
};

}  // namespace
}  // namespace snap_steps

Snapped snap_round(const std::vector<Segment>& segs, const std::vector<std::uint32_t>& next,
                   Contacts& contacts, SegmentSearch& search) {
  Snapped out;
  out.touched.swap(contacts.touched);
  // The vertices are every segment's start and every split point; an end that starts no segment
  // (an open run's: collinear_merge.hpp) joins them as a split point at the end, which routing
  // skips.
  for (std::uint32_t s = 0; s < segs.size(); ++s)
    if (segs[next[s]].a != segs[s].b) contacts.splits.emplace_back(s, segs[s].b);
  // No crossing at a non-integer point: every contact is an exact split and nothing moves.
  if (contacts.hot.empty()) {
    Fragments routed = snap_steps::route(segs, snap_steps::Closure{}, contacts.splits);
    out.fragments.swap(routed);
    return out;
  }
  snap_steps::SnapRounds(segs, contacts, search).run(out);
  return out;
}

Snapped node_and_snap_round(const std::vector<Segment>& segs,
                            const std::vector<std::uint32_t>& next, bool simple_rings,
                            std::size_t* intersections) {
  SegmentSearch search(segs, next);
  Contacts contacts = find_contacts(segs, next, search, {simple_rings});
  if (intersections) *intersections = contacts.intersections;
  return snap_round(segs, next, contacts, search);
}

}  // namespace edgeland::detail
