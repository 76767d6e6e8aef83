// Snap rounding's safety re-check (snap_rounding_steps.hpp): fragments of moved segments
// against everything they may meet that the snap-rounding theorem does not already cover,
// tested exactly. clip/README.md, "Which fragment pairs the re-check tests", says which pairs
// that is and why the rest need no test.
#include <algorithm>
#include <limits>

#include "edgeland/kernel/pixel.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "offsets.hpp"
#include "snap_rounding_steps.hpp"

namespace edgeland::detail::snap_steps {
namespace {

// All fragments: the listed ones (ids 0 .. F-1) and, for every segment s without listed
// fragments, the segment itself (id F + s).
class AllFragments {
 public:
  AllFragments(const std::vector<Segment>& segs, const std::vector<Fragment>& listed)
      : segs_(segs), listed_(listed) {
    first_.assign(segs.size() + 1, 0);
    for (const Fragment& f : listed) ++first_[f.parent + 1];
    add_up_counts(first_);
  }
  std::uint32_t listed_count() const { return static_cast<std::uint32_t>(listed_.size()); }
  std::uint32_t id_bound() const {
    return listed_count() + static_cast<std::uint32_t>(segs_.size());
  }
  std::uint32_t segment_count() const { return static_cast<std::uint32_t>(segs_.size()); }
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
    for (std::uint32_t s = 0; s < segment_count(); ++s) unlisted += !has_listed(s);
    return listed_.size() + unlisted;
  }

 private:
  const std::vector<Segment>& segs_;
  const std::vector<Fragment>& listed_;
  ScratchVector<std::uint32_t> first_;
};

// Few segments (a flat search): each segment looks up the vertices in its box grown by a unit in
// `loose` (sorted, so by x first) instead of each vertex scanning all segments; the same pairs
// meet the exact test.
void mark_off_by_segment(const std::vector<Segment>& segs, const std::vector<Point64>& loose,
                         std::vector<std::uint8_t>& off) {
  for (std::uint32_t s = 0; s < segs.size(); ++s) {
    const Box64 reach = grown(segment_box(segs[s]), 1);  // the vertices whose pixel_box it meets
    auto it = std::lower_bound(loose.begin(), loose.end(), reach.min.x,
                               [](Point64 p, std::int64_t x) { return p.x < x; });
    for (; it != loose.end() && it->x <= reach.max.x; ++it)
      if (it->y >= reach.min.y && it->y <= reach.max.y &&
          segment_meets_closed_pixel(segs[s], *it) && !on_segment(*it, segs[s])) {
        off[s] = true;
        break;
      }
  }
}

// Segments whose route may differ from the route classic snap rounding would give them if every
// vertex pixel were hot too: those meeting the closed pixel of a vertex that is neither hot nor
// on them. Every other segment's route is exactly that classic route: it already passes through
// its own ends and split points and through every hot pixel it meets. Read from the closure's
// record when it has a complete one (its vertices include every end and split point), found
// through the segment grid otherwise.
void off_classic_routes(const std::vector<Segment>& segs, SegmentsNear& near,
                        const std::vector<SegmentPoint>& splits, const PointSet& is_hot,
                        const Closure& closure, std::vector<std::uint8_t>& off) {
  off.assign(segs.size(), false);
  if (closure.near_vertex_complete) {
    for (const auto& [s, p] : closure.near_vertex)
      if (!is_hot.contains(p)) off[s] = true;
    return;
  }
  ScratchVector<Point64> loose;  // vertices that are not hot
  loose.reserve(segs.size() + splits.size());
  for (const Segment& s : segs)
    if (!is_hot.contains(s.a)) loose.push_back(s.a);  // every end starts a segment
  for (const auto& sp : splits)
    if (!is_hot.contains(sp.second)) loose.push_back(sp.second);
  std::sort(loose.begin(), loose.end());
  loose.erase(std::unique(loose.begin(), loose.end()), loose.end());
  if (near.flat()) return mark_off_by_segment(segs, loose, off);
  for (Point64 p : loose)
    near.for_each(p, [&](std::uint32_t s) {
      if (!off[s] && segment_meets_closed_pixel(segs[s], p) && !on_segment(p, segs[s]))
        off[s] = true;
    });
}

// The pair tests of one re-check. Split points are reported by fragment id (AllFragments).
class PairCheck {
 public:
  PairCheck(const AllFragments& all, const std::vector<std::uint8_t>& moved,
            std::vector<std::uint8_t>& touched, Contacts& into)
      : found(into), all_(all), touched_(touched) {
    is_moved_.assign(all.listed_count(), false);
    which_.reserve(all.listed_count());
    for (std::uint32_t i = 0; i < all.listed_count(); ++i) {  // moved segments are always listed
      if (!moved[all.parent(i)]) continue;
      which_.push_back(i);
      is_moved_[i] = true;
    }
  }
  const std::vector<std::uint32_t>& moved_fragments() const { return which_; }
  bool moved(std::uint32_t id) const { return id < all_.listed_count() && is_moved_[id]; }
  void operator()(std::uint32_t f, std::uint32_t g) {
    if (classify_pair(all_.seg(f), f, all_.seg(g), g, found) != Meeting::kNone)
      touched_[all_.parent(f)] = touched_[all_.parent(g)] = true;
  }
  Contacts& found;

 private:
  const AllFragments& all_;
  std::vector<std::uint8_t>& touched_;
  ScratchVector<std::uint8_t> is_moved_;
  ScratchVector<std::uint32_t> which_;
};

// Few moved fragments and few splits: query the run index. Every fragment lies within one unit
// of its segment's box (the query boxes grow by 2 to be safe). `off` (empty: unknown) leaves
// out pairs on their classic routes.
void check_by_box_queries(const AllFragments& all, const SegmentIndex& index,
                          const std::vector<std::uint8_t>& off, PairCheck& check) {
  const auto& which = check.moved_fragments();
  ScratchVector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  auto add = [&](std::uint32_t f, std::uint32_t g) {
    if (f == g || (check.moved(g) && g < f)) return;  // a moved pair is seen from both sides
    if (!off.empty() && !off[all.parent(f)] && !off[all.parent(g)]) return;
    // Fragments whose boxes miss each other do not meet (the queries found their segments).
    if (!boxes_overlap(all.seg(f), all.seg(g))) return;
    pairs.emplace_back(std::min(f, g), std::max(f, g));
  };
  ScratchVector<Box64> boxes;
  boxes.resize(which.size());
  for (std::size_t k = 0; k < which.size(); ++k)
    boxes[k] = grown(segment_box(all.seg(which[k])), 2);
  index.query(boxes, [&](std::uint32_t k, std::uint32_t s) {
    all.for_each_of(s, [&](std::uint32_t g) { add(which[k], g); });
  });
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for (const auto& [f, g] : pairs) check(f, g);
}

// Many moved fragments (spiky inputs: cut short at every crossing): every fragment is walked
// through a grid (segment_grid.hpp), which proposes each pair once; only pairs with a moved
// fragment and one off its classic route are tested.
void check_by_grid_walk(const AllFragments& all, const std::vector<std::uint8_t>& off,
                        PairCheck& check) {
  ScratchVector<std::uint32_t> ids;
  ScratchVector<Segment> all_segments;
  ids.reserve(all.count());
  all_segments.reserve(all.count());
  for (std::uint32_t s = 0; s < all.segment_count(); ++s)
    all.for_each_of(s, [&](std::uint32_t id) {
      ids.push_back(id);
      all_segments.push_back(all.seg(id));
    });
  SegmentGrid grid(all_segments);
  grid.order_if_crowded(all_segments);  // long near-parallel fragments (zigzag stars)
  grid.for_each_candidate_pair([&](std::uint32_t i, std::uint32_t j) {
    if ((check.moved(ids[i]) || check.moved(ids[j])) &&
        (off[all.parent(ids[i])] || off[all.parent(ids[j])]) &&
        boxes_overlap(all_segments[i], all_segments[j]))
      check(ids[i], ids[j]);
  });
}

// Few fragments off their classic routes among many (zigzag stars of 10^6 vertices: those of
// 1,059 of 2 * 10^6 segments): a grid of the off fragments alone, laid over the extent of all
// fragments, and every fragment walked through it. An off fragment and a fragment sharing a
// point share that point's cell, so this tests the pairs of check_by_grid_walk that can meet,
// each once (a pair of two off fragments from its larger id), without a grid of every fragment
// (at 10^6 it was 2.4 GB and most of the re-check's time).
void check_against_off_fragments(const AllFragments& all, const std::vector<std::uint8_t>& off,
                                 PairCheck& check) {
  ScratchVector<std::uint32_t> off_ids;
  ScratchVector<Segment> off_segments;
  Box64 extent = segment_box(all.seg(0));
  for (std::uint32_t s = 0; s < all.segment_count(); ++s)
    all.for_each_of(s, [&](std::uint32_t id) {
      extent.expand(segment_box(all.seg(id)));
      if (!off[s]) return;
      off_ids.push_back(id);
      off_segments.push_back(all.seg(id));
    });
  SegmentGrid grid(off_segments, extent);
  ScratchVector<std::uint32_t> stamp;  // the fragment that last met each off fragment
  stamp.assign(off_ids.size(), std::numeric_limits<std::uint32_t>::max());
  for (std::uint32_t s = 0; s < all.segment_count(); ++s)
    all.for_each_of(s, [&](std::uint32_t g) {
      const Segment& walked = all.seg(g);
      grid.for_each_along(walked, [&](std::uint32_t k) {
        const std::uint32_t f = off_ids[k];
        if (stamp[k] == g || f == g || (off[s] && g < f)) return;
        stamp[k] = g;
        if ((check.moved(f) || check.moved(g)) && boxes_overlap(all.seg(f), walked))
          check(std::min(f, g), std::max(f, g));
      });
    });
}

// Few segments (a flat search): every moved fragment against every fragment, the pairs of the
// grid walk above exactly (a moved one, one off its classic route, boxes overlapping), each once,
// without building the grid.
void check_moved_against_all(const AllFragments& all, const std::vector<std::uint8_t>& off,
                             PairCheck& check) {
  for (std::uint32_t f : check.moved_fragments()) {
    const Segment& a = all.seg(f);
    for (std::uint32_t s = 0; s < all.segment_count(); ++s)
      all.for_each_of(s, [&](std::uint32_t g) {
        if (g == f || (check.moved(g) && g < f)) return;  // a moved pair is seen from both sides
        if ((off[all.parent(f)] || off[all.parent(g)]) && boxes_overlap(a, all.seg(g))) check(f, g);
      });
  }
}

// How many fragments have a parent off its classic route.
std::size_t off_fragments(const AllFragments& all, const std::vector<std::uint8_t>& off) {
  std::size_t count = 0;
  for (std::uint32_t s = 0; s < all.segment_count(); ++s)
    if (off[s]) all.for_each_of(s, [&](std::uint32_t) { ++count; });
  return count;
}

bool any(const std::vector<std::uint8_t>& v) { return std::find(v.begin(), v.end(), 1) != v.end(); }

// The listed fragments after cutting fragments (by AllFragments id) at exact split points.
Fragments split_fragments(const AllFragments& all, const std::vector<SegmentPoint>& splits) {
  ScratchVector<Segment> pieces;
  pieces.resize(all.id_bound());
  for (std::uint32_t id = 0; id < all.id_bound(); ++id) pieces[id] = all.seg(id);
  const Fragments cut = route(pieces, Closure{}, splits);  // by piece id
  ScratchVector<std::uint32_t> first;
  first.assign(all.id_bound() + 1, 0);
  for (const Fragment& f : cut) ++first[f.parent + 1];
  add_up_counts(first);
  Fragments out;
  for (std::uint32_t s = 0; s < all.segment_count(); ++s)
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

// On the box path, pairs on their classic routes are left out only when the closure recorded
// which segments pass near which vertices (finding that out afresh would cost a pass over all
// vertices); the grid path always asks.
Rechecked recheck(const std::vector<Segment>& segs, Fragments fragments, const Closure& closure,
                  SegmentSearch& search, const std::vector<SegmentPoint>& splits,
                  const PointSet& is_hot, std::vector<std::uint8_t>& touched) {
  Rechecked out;
  const AllFragments all(segs, fragments);
  PairCheck check(all, closure.moved, touched, out.found);
  ScratchVector<std::uint8_t> off;  // empty: unknown
  auto off_classic = [&] { off_classic_routes(segs, search.near, splits, is_hot, closure, off); };
  const std::size_t total = all.count();
  if (8 * check.moved_fragments().size() < total && total < 2 * segs.size()) {
    // (Not reached by tests: no re-check with few moved fragments follows a closure that
    // recorded its near-vertex passes.)
    if (closure.near_vertex_complete) off_classic();
    if (off.empty() || any(off)) check_by_box_queries(all, search.index, off, check);
  } else {
    off_classic();
    if (!any(off)) {
      // Every fragment is on its classic route: nothing to test.
    } else if (search.index.flat()) {
      check_moved_against_all(all, off, check);
    } else if (16 * off_fragments(all, off) < total) {
      check_against_off_fragments(all, off, check);
    } else {
      check_by_grid_walk(all, off, check);
    }
  }
  if (!out.found.hot.empty()) return out;
  // Only exact integer splits remain, if any (snapped fragments landing on vertices or
  // overlapping collinearly): split and finish; nothing moves.
  if (out.found.splits.empty()) {
    out.fragments.swap(fragments);
  } else {
    Fragments split = split_fragments(all, out.found.splits);
    out.fragments.swap(split);
  }
  return out;
}

}  // namespace edgeland::detail::snap_steps
