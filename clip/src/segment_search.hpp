#pragma once
// The search structures over one edge list's segments that noding and snap rounding share:
// the run index (segment_index.hpp) and, when built, a segment grid answering "which segments
// pass near this point".
#include <cstdint>
#include <optional>
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "grown_box.hpp"
#include "segment_grid.hpp"
#include "segment_index.hpp"

namespace edgeland::detail {

// The input segments near a point, found through a SegmentGrid of the input (noding hands its
// own over on spiky inputs; otherwise it is built on first use). With many hot pixels or moved
// segments, asking at each point is far cheaper than walking every long segment through a grid
// of points: a point's cells hold a few dozen segments, while a spike crosses hundreds of point
// cells.
class SegmentsNear {
 public:
  // A flat `index` (segment_index.hpp: few segments) answers by a scan of its boxes instead.
  SegmentsNear(const std::vector<Segment>& segs, const SegmentIndex& index)
      : segs_(segs), index_(index) {}
  // Where noding leaves the grid it walked, if it walked one.
  std::optional<SegmentGrid>& grid() { return grid_; }
  // Whether a grid was walked or built (possibly released since: the next query rebuilds it).
  bool has_grid() const { return grid_.has_value() || released_; }
  // Frees the grid while no query is expected: snap rounding's routing and re-check, once the
  // closure has recorded what they would ask (at zigzag stars of 10^5 vertices the grid was 61
  // of the 145 MB held then; issue 28). A later query rebuilds it, ordered if crowded.
  void release_grid() {
    released_ = released_ || grid_.has_value();
    grid_.reset();
  }
  // Whether the segments are few enough to be scanned (segment_index.hpp, flat searches).
  bool flat() const { return index_.flat(); }
  // visit(s) once for every segment with a point within L-infinity distance 1 of p (and for
  // some farther ones: callers test exactly).
  template <class F>
  void for_each(Point64 p, F&& visit) {
    if (index_.flat()) return index_.query_flat(pixel_box(p), visit);
    if (!grid_) {
      grid_.emplace(segs_);
      if (released_) grid_->order_if_crowded(segs_);  // ordered when crowded, as noding's was
    }
    if (stamp_.empty() || token_ == kUnstamped - 1) {
      stamp_.assign(segs_.size(), kUnstamped);
      token_ = 0;
    }
    const std::uint32_t token = ++token_;
    grid_->for_each_in_box(pixel_box(p), [&](std::uint32_t s) {
      if (stamp_[s] == token) return;
      stamp_[s] = token;
      visit(s);
    });
  }

 private:
  static constexpr std::uint32_t kUnstamped = 0xffffffffu;
  const std::vector<Segment>& segs_;
  const SegmentIndex& index_;
  std::optional<SegmentGrid> grid_;
  bool released_ = false;
  ScratchVector<std::uint32_t> stamp_;
  std::uint32_t token_ = 0;
};

// Both, over segments whose ring successors are next[s]. Keeps references to both vectors.
struct SegmentSearch {
  SegmentSearch(const std::vector<Segment>& segments, const std::vector<std::uint32_t>& next)
      : index(segments, next), near(segments, index) {}
  SegmentIndex index;
  SegmentsNear near;
};

}  // namespace edgeland::detail
