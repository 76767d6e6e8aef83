#pragma once
// The steps of snap_round (snap_rounding.hpp), internal to its sources:
//   close_hot_set   grows the hot pixels until no moved segment would jump over a vertex
//                   (snap_closure.cpp);
//   route           cuts every segment at its split points and the centres of the hot pixels
//                   it meets (snap_rounding.cpp);
//   recheck         tests the moved fragments exactly against what they may meet; what it
//                   finds makes more pixels hot, or only splits (snap_recheck.cpp).
#include <cstdint>
#include <utility>
#include <vector>

#include "edgeland/kernel/scratch.hpp"
#include "grown_box.hpp"
#include "noding.hpp"
#include "point_set.hpp"
#include "segment_search.hpp"
#include "snap_rounding.hpp"

namespace edgeland::detail::snap_steps {

// (segment, point) pairs: an exact split point of a segment, or a hot centre it meets.
using SegmentPoint = std::pair<std::uint32_t, Point64>;

// Points on the way of segments, grouped by segment (CSR: one array, no allocation per segment).
class StopsOf {
 public:
  StopsOf(std::size_t segments, const std::vector<SegmentPoint>& stops);
  // Appends the points of segment s to out.
  void append(std::uint32_t s, std::vector<Point64>& out) const {
    out.insert(out.end(), points_.begin() + begin_[s], points_.begin() + begin_[s + 1]);
  }

 private:
  ScratchVector<std::uint32_t> begin_;
  ScratchVector<Point64> points_;
};

// The hot set and what it moved.
struct Closure {
  ScratchVector<Point64> hot;  // all hot pixel centres
  // (segment, hot index)
  ScratchVector<std::pair<std::uint32_t, std::uint32_t>> meets;
  ScratchVector<std::uint8_t> moved;  // by segment
  // (segment, vertex) for every vertex (end or split point) not on the segment whose closed pixel
  // the segment meets; complete once a grid pass over all vertices has run (off_classic_routes).
  ScratchVector<SegmentPoint> near_vertex;
  bool near_vertex_complete = false;
};

// What close_hot_set reads: the segments, their search structures, and the vertices (every
// segment's start and every exact split point; split_points sorted and unique).
struct ClosureInput {
  const std::vector<Segment>& segs;
  SegmentSearch& search;
  const std::vector<Point64>& split_points;
  const StopsOf& splits_of;
};

// Grows the hot set until it is closed (snap_closure.cpp says by which rules). `fresh` holds the
// new hot centres on entry, already in is_hot, and is empty on return. classic: the fallback
// rule of Guibas-Marimont snap rounding.
void close_hot_set(const ClosureInput& in, bool classic, PointSet& is_hot, Closure& c,
                   std::vector<Point64>& fresh);

// Every segment with stops (split points, centres of hot pixels it meets) cut at them, in order
// along it. Segments without stops are their own fragment and are not listed.
Fragments route(const std::vector<Segment>& segs, const Closure& c,
                const std::vector<SegmentPoint>& splits);

// What the re-check found: `found.hot` lists the pixels of crossings that survived (make them
// hot and close again; found.splits then joins the vertices). With none, `fragments` are the
// final fragments: as routed, or cut at the exact splits found.
struct Rechecked {
  Contacts found;
  Fragments fragments;
};

// Fragments of moved segments against everything they may meet that the snap-rounding theorem
// does not already cover, exactly (snap_recheck.cpp). touched: marks segments found meeting.
Rechecked recheck(const std::vector<Segment>& segs, Fragments fragments, const Closure& closure,
                  SegmentSearch& search, const std::vector<SegmentPoint>& splits,
                  const PointSet& is_hot, std::vector<std::uint8_t>& touched);

}  // namespace edgeland::detail::snap_steps
