#pragma once
// Candidate search for noding and snap rounding: which segments' boxes overlap each other, or
// overlap given query boxes.
//
// Consecutive segments of one ring that run monotonically in x and in y are grouped into runs of
// at most kRunLength segments (Boost.Geometry calls them sections). A run's box is the box of its
// two ends, so the sweep sorts runs, not segments: n / kRunLength items for a smooth ring. Two
// segments of one run never have overlapping boxes unless they are consecutive (monotone:
// box i ends where box i + 1 begins), and consecutive ones only share their common endpoint.
// Between two runs whose boxes overlap, monotonicity lets a two-pointer walk visit exactly the
// segment pairs whose x-ranges overlap. Spiky rings give runs of one or two segments and the
// cost of a plain box sweep (box_sweep.hpp).
//
// A few segments (up to kFlatUpTo: the landscape's per-cell overlays have 30-130) skip all of
// that: their boxes go into one flat array sorted by min x, pairs come from a plain sweep over
// it and queries from a scan, and no run box, run sweep or grid is built. The flat answers are
// the run answers exactly: the same pairs (consecutive segments of one run left out by the same
// greedy runs) and the same (query, segment) matches, in another order.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "box_grid.hpp"
#include "box_sweep.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/scratch.hpp"

namespace edgeland::detail {

class SegmentIndex {
 public:
  // Longer runs mean fewer boxes to sort and pair; the two-pointer walk keeps pairs inside
  // overlapping runs cheap. Smooth stars (10^3 to 10^5 vertices) ran fastest at 64 of
  // 16 / 32 / 64 / 128; the carving workload did not notice.
  static constexpr std::uint32_t kRunLength = 64;
  static constexpr std::size_t kGridFrom = 256;  // runs
  // Up to this many segments the search is flat (above). Measured on the landscape's edits
  // (bench/README.md, "Issue 28, second pass"): the set-up of runs, sweeps and grids was most
  // of the search's cost on 30-130 segments. 256 leaves room above those without letting the
  // scans, which grow with the square of the count, meet large inputs (not tuned further).
  static constexpr std::size_t kFlatUpTo = 256;

  // next[s]: the segment that follows s along its ring (segments of a ring are consecutive).
  // Keeps a reference to `segments`, which must outlive the index.
  // flat_up_to: the most segments searched flat (tests set 0 or more to compare the two ways).
  SegmentIndex(const std::vector<Segment>& segments, const std::vector<std::uint32_t>& next,
               std::size_t flat_up_to = kFlatUpTo);

  // visit(i, j) once per unordered pair of distinct segments whose closed boxes overlap, except
  // consecutive segments of one run (ring neighbours meeting only at their shared endpoint),
  // and with across_rings_only, except every pair from one ring (the caller knows its rings are
  // simple: two segments of one ring meet only as neighbours, at their shared endpoint).
  template <class F>
  void for_each_overlapping_pair(F&& visit, bool across_rings_only = false) const;

  // visit(k, s) for every segment s whose closed box overlaps boxes[k].
  template <class F>
  void query(const std::vector<Box64>& boxes, F&& visit) const;

  // Pairs of runs whose x-ranges overlap, counted up to a little past `limit`: about the work
  // of for_each_overlapping_pair.
  std::size_t x_overlapping_run_pairs(std::size_t limit) const {
    build_runs();
    return x_overlapping_pairs(run_sweep(), limit);
  }

  // Frees the runs, their boxes and their sweep (rebuilt if asked again): once noding has taken
  // a grid instead, they were only counted, and at scale they are tens of megabytes, so they go
  // back to the heap, not to the scratch spares.
  void release_runs() const {
    built_ = false;
    std::vector<Run>().swap(runs_);
    std::vector<Box64>().swap(run_boxes_);
    std::vector<SweepBox>().swap(run_sweep_);
  }

  // Segments per run on average, times 16 (an integer: the caller's choice of search only
  // needs a rough figure). Counts the runs without building them.
  std::size_t run_length_x16() const;

  Box64 box(std::uint32_t s) const { return segment_box((*segments_)[s]); }

  // Whether the search is flat (few segments: no runs, no grid; see above).
  bool flat() const { return segments_->size() <= flat_up_to_; }

  // visit(s) for every segment s whose closed box overlaps q (flat searches only).
  template <class F>
  void query_flat(const Box64& q, F&& visit) const;

 private:
  struct Run {
    std::uint32_t first, last;  // segment ids, inclusive, consecutive along the ring
    std::uint32_t ring;         // the first segment of its ring
    bool x_decreasing;          // walk last -> first to see x increase
  };
  // The k-th segment of run r in order of increasing x.
  std::uint32_t at(const Run& r, std::uint32_t k) const {
    return r.x_decreasing ? r.last - k : r.first + k;
  }
  static std::uint32_t size(const Run& r) { return r.last - r.first + 1; }
  // Pairs of segments of runs a and b whose boxes overlap.
  template <class F>
  void pairs_between(std::uint32_t a, std::uint32_t b, F& visit) const;
  // The greedy run starting at segment s: its last segment, and whether x decreases along it.
  struct RunEnd {
    std::uint32_t last;
    bool x_decreasing;
  };
  RunEnd run_end(std::uint32_t s) const;
  // Fills run_ends_ once, for whichever of run_length_x16 and build_runs asks first.
  void find_run_ends() const;
  // Builds runs_ and run_boxes_ on first use: noding through the segment grid without hot
  // pixels (checkerboards, tiles) never queries the index, and building the runs was a few
  // percent of such an operation.
  void build_runs() const;
  // Fills flat_ (boxes by min x) and ring_ on first use.
  void build_flat() const;
  void sort_flat() const;
  // Fills continues_run_ on first use.
  void mark_runs() const;
  template <class F>
  void flat_pairs(F& visit, bool across_rings_only) const;

  const std::vector<Segment>* segments_;  // boxes are computed, not stored: less memory traffic
  const std::vector<std::uint32_t>* next_;
  std::size_t flat_up_to_;
  mutable bool built_ = false;
  mutable ScratchVector<RunEnd> run_ends_;  // in segment order
  mutable ScratchVector<Run> runs_;
  mutable ScratchVector<Box64> run_boxes_;
  // Run boxes, sorted_for_sweep; sorted on first use (noding through the segment grid and
  // inputs without hot pixels never need them).
  const std::vector<SweepBox>& run_sweep() const {
    if (run_sweep_.size() != run_boxes_.size()) sort_for_sweep(run_boxes_, run_sweep_);
    return run_sweep_;
  }
  mutable ScratchVector<SweepBox> run_sweep_;
  // Flat searches: every segment's box sorted by min x; whether segment s follows s - 1 in one
  // run (the pair the runs leave out); the first segment of each segment's ring.
  mutable ScratchVector<SweepBox> flat_;
  mutable ScratchVector<std::uint8_t> continues_run_;
  mutable ScratchVector<std::uint32_t> ring_;
};

template <class F>
void SegmentIndex::pairs_between(std::uint32_t a, std::uint32_t b, F& visit) const {
  // Along a run in increasing-x order both ends of the segments' x-ranges are non-decreasing,
  // so the segments of r2 overlapping one of r1 in x form a window that only moves forward.
  // Only segments within the common part of the two runs' boxes can meet: each run is entered
  // by binary search at its first segment reaching that part, and left past it. (Runs of one
  // ring that follow each other share only an end, and a long run often reaches the other
  // run's box with a few segments only.)
  const Run &r1 = runs_[a], &r2 = runs_[b];
  const Box64 &b1 = run_boxes_[a], &b2 = run_boxes_[b];
  const std::int64_t lo_x = std::max(b1.min.x, b2.min.x), hi_x = std::min(b1.max.x, b2.max.x);
  const std::int64_t lo_y = std::max(b1.min.y, b2.min.y), hi_y = std::min(b1.max.y, b2.max.y);
  auto first_reaching = [&](const Run& r) {
    std::uint32_t lo = 0, hi = size(r);
    while (lo < hi) {
      const std::uint32_t mid = (lo + hi) / 2;
      if (box(at(r, mid)).max.x < lo_x)
        lo = mid + 1;
      else
        hi = mid;
    }
    return lo;
  };
  const std::uint32_t n1 = size(r1), n2 = size(r2);
  std::uint32_t from = first_reaching(r2);
  for (std::uint32_t k1 = first_reaching(r1); k1 < n1; ++k1) {
    const std::uint32_t s = at(r1, k1);
    const Box64 bs = box(s);
    if (bs.min.x > hi_x) break;
    if (bs.min.y > hi_y || bs.max.y < lo_y) continue;
    while (from < n2 && box(at(r2, from)).max.x < bs.min.x) ++from;
    for (std::uint32_t k2 = from; k2 < n2; ++k2) {
      const std::uint32_t t = at(r2, k2);
      const Box64 bt = box(t);
      if (bt.min.x > bs.max.x) break;
      if (bt.min.y <= bs.max.y && bs.min.y <= bt.max.y) visit(s, t);
    }
  }
}

template <class F>
void SegmentIndex::flat_pairs(F& visit, bool across_rings_only) const {
  if (flat_.empty()) build_flat();
  // Consecutive segments of one run are of one ring: only needed when rings are not left out.
  if (!across_rings_only) mark_runs();
  for (std::size_t a = 0; a < flat_.size(); ++a) {
    const SweepBox& x = flat_[a];
    for (std::size_t b = a + 1; b < flat_.size() && flat_[b].min_x <= x.max_x; ++b) {
      const SweepBox& y = flat_[b];
      if (y.min_y > x.max_y || x.min_y > y.max_y) continue;
      const std::uint32_t i = std::min(x.id, y.id), j = std::max(x.id, y.id);
      if (across_rings_only ? ring_[i] == ring_[j] : j == i + 1 && continues_run_[j]) continue;
      visit(i, j);
    }
  }
}

template <class F>
void SegmentIndex::query_flat(const Box64& q, F&& visit) const {
  if (flat_.empty()) build_flat();
  for (const SweepBox& b : flat_) {
    if (b.min_x > q.max.x) break;
    if (b.max_x >= q.min.x && b.min_y <= q.max.y && q.min.y <= b.max_y) visit(b.id);
  }
}

template <class F>
void SegmentIndex::for_each_overlapping_pair(F&& visit, bool across_rings_only) const {
  if (flat()) return flat_pairs(visit, across_rings_only);
  build_runs();
  auto between = [&](std::uint32_t a, std::uint32_t b) {
    if (across_rings_only && runs_[a].ring == runs_[b].ring) return;
    pairs_between(a, b, visit);
  };
  // Many runs: a grid, whose cost follows the boxes' local density; the sweep compares each
  // run with every run spanning its x, which on grid-like inputs is a whole column of them.
  if (runs_.size() > kGridFrom)
    for_each_overlapping_pair_in_grid(run_boxes_, between);
  else
    detail::for_each_overlapping_pair(run_sweep(), between);
}

template <class F>
void SegmentIndex::query(const std::vector<Box64>& boxes, F&& visit) const {
  if (flat()) {
    for (std::uint32_t k = 0; k < boxes.size(); ++k)
      query_flat(boxes[k], [&](std::uint32_t s) { visit(k, s); });
    return;
  }
  build_runs();
  detail::for_each_overlapping_pair(sorted_for_sweep(boxes), run_sweep(),
                                    [&](std::uint32_t k, std::uint32_t r) {
                                      // Along the run in increasing-x order the segments' x-ranges
                                      // only move right: skip by binary search to the first that
                                      // reaches the query box, stop at the first past it.
                                      const Run& run = runs_[r];
                                      const Box64& q = boxes[k];
                                      std::uint32_t lo = 0, hi = size(run);
                                      while (lo < hi) {
                                        const std::uint32_t mid = (lo + hi) / 2;
                                        if (box(at(run, mid)).max.x < q.min.x)
                                          lo = mid + 1;
                                        else
                                          hi = mid;
                                      }
                                      for (std::uint32_t i = lo; i < size(run); ++i) {
                                        const std::uint32_t s = at(run, i);
                                        const Box64 b = box(s);
                                        if (b.min.x > q.max.x) break;
                                        if (b.overlaps(q)) visit(k, s);
                                      }
                                    });
}

}  // namespace edgeland::detail
