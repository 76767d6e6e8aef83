#pragma once
// Stable snap rounding: turns segments with arbitrary crossings into integer fragments that
// meet only at shared endpoints or overlap exactly. See clip/README.md for the argument.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "noding.hpp"
#include "segment_search.hpp"

namespace edgeland::detail {

struct Fragment {
  Segment seg;           // integer endpoints, seg.a != seg.b
  std::uint32_t parent;  // index of the input segment it comes from (same direction)
};

// Fragment lists recycle their storage per thread (scratch.hpp).
using Fragments = ScratchVector<Fragment>;

// What snap rounding hands the plane graph.
struct Snapped {
  // The fragments of the segments that snap rounding cuts or moves, in input order (each such
  // segment's fragments run from its start to its end). Every other segment is its own single
  // fragment and is not listed: on smooth inputs that is nearly all of them.
  Fragments fragments;
  // touched[s] is false only for input segments that yield themselves as their one fragment and
  // share no point with any other fragment except their ring neighbours' at their common
  // endpoints. The plane graph chains such segments (plane_graph.hpp).
  ScratchVector<std::uint8_t> touched;
  // Bounding boxes of the input segments that snap rounding moved: nothing farther than one
  // unit from these boxes can be affected by the rounding.
  ScratchVector<Box64> moved_boxes;
  std::size_t hot_pixels = 0;
};

// Snap rounds `segs` given all their contacts (find_contacts over the same `search`, not
// stopped; its touched flags move into the result). next[s] is the segment following s along
// its ring; a segment need not end where its `next` starts (collinear_merge.hpp cuts rings into
// open runs): such an end is a vertex like any other, and is added to contacts.splits.
// Throws std::logic_error if the safety re-check does not converge.
Snapped snap_round(const std::vector<Segment>& segs, const std::vector<std::uint32_t>& next,
                   Contacts& contacts, SegmentSearch& search);

// Noding (no screen, no overlap budget) and snap rounding in one call, for callers that need
// no more of the contacts than how many pairs met (`intersections`, when not null).
Snapped node_and_snap_round(const std::vector<Segment>& segs,
                            const std::vector<std::uint32_t>& next, bool simple_rings,
                            std::size_t* intersections = nullptr);

}  // namespace edgeland::detail
