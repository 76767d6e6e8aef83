#pragma once
// Stable snap rounding: turns segments with arbitrary crossings into integer fragments that
// meet only at shared endpoints or overlap exactly. See clip/README.md for the argument.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/recycled_vector.hpp"

namespace edgeland::detail {

struct Fragment {
  Segment seg;            // integer endpoints, seg.a != seg.b
  std::uint32_t parent;   // index of the input segment it comes from (same direction)
};

struct SnapStats {
  // Bounding boxes of the input segments that snap rounding moved: nothing farther than one
  // unit from these boxes can be affected by the rounding.
  std::vector<Box64> moved_boxes;
  std::size_t intersections = 0;
  std::size_t hot_pixels = 0;
  // touched[s] is false only for input segments that yield themselves as their one fragment and
  // share no point with any other fragment except their ring neighbours' at their common
  // endpoints. The plane graph chains such segments (planar_graph.hpp).
  std::vector<std::uint8_t> touched;
  // Only with screen_channel: noding found a contact proving an operand invalid and stopped
  // (noding.hpp); snap_round then returns no fragments.
  bool operand_invalid = false;
  // Noding stopped at its overlap budget (noding.hpp); snap_round then returns no fragments.
  bool overlap_heavy = false;
};

// The fragments of the segments that snap rounding cuts or moves, in input order (each such
// segment's fragments run from its start to its end). Every other segment is its own single
// fragment and is not listed: on smooth inputs that is nearly all of them.
// next[s] is the segment following s along its ring. simple_rings: every ring is strictly simple
// (validated operands; normalize's rings are not), which spares the noding pairs within a ring.
// Throws std::logic_error if the safety re-check does not converge.
// Fragment lists recycle their storage per thread (recycled_vector.hpp).
struct FragmentsBuffer;
using Fragments = RecycledVector<FragmentsBuffer, Fragment>;

// A segment need not end where its `next` starts (collinear_merge.hpp cuts rings into open
// runs); such an end is a vertex like any other.
// screen_channel, overlap_budget: see find_contacts (noding.hpp).
Fragments snap_round(const std::vector<Segment>& segments, const std::vector<std::uint32_t>& next,
                     bool simple_rings, SnapStats& stats,
                     const std::vector<std::uint8_t>* screen_channel = nullptr,
                     std::size_t overlap_budget = std::numeric_limits<std::size_t>::max());

}  // namespace edgeland::detail
