#pragma once
// The candidate pairs of noding (noding.cpp) and of the fragment checker (check_fragments.cpp):
// every pair of segments whose closed boxes overlap, found through the run index or through a
// walk of a segment grid. One choice between the two searches, by their counted work, so the
// checker costs what noding costs on as many segments.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "segment_grid.hpp"
#include "segment_index.hpp"

namespace edgeland::detail {

// Whether a grid walk is worth building: many segments in short runs (spiky or zigzag rings)
// leave the run index little to group, and their long diagonals make box overlap a weak filter.
inline bool runs_are_short(const SegmentIndex& index, std::size_t segments) {
  constexpr std::size_t kGridWalkFrom = 64;                   // segments
  constexpr std::size_t kGridWalkBelowRunLengthX16 = 16 * 3;  // runs shorter than 3 segments
  return segments >= kGridWalkFrom && index.run_length_x16() < kGridWalkBelowRunLengthX16;
}

// Whether the run index would propose fewer pairs than the grid's cells hold (before the
// crowded cells are ordered): a grid sized for
// spikes fails on long parallel segments side by side (comb teeth 10^8 long and 80 apart: 10^4
// of them per cell), whose runs' x-ranges barely overlap. Only counted when the cells hold many.
inline bool grid_walk_is_worse(const SegmentGrid& grid, const SegmentIndex& index,
                               std::size_t segments) {
  const std::size_t cell_pairs = grid.cell_pairs();
  return cell_pairs > 16 * segments + 4096 &&
         index.x_overlapping_run_pairs(cell_pairs) < cell_pairs;
}

// visit(i, j) once for every pair of `segs` whose closed boxes overlap, except consecutive
// segments of one monotone run of the index (they meet only at their common end): through
// `grid` when given (a SegmentGrid of segs) and not worse than the index, else through the
// index; a grid walked with many pairs per cell has its crowded cells ordered first (left so
// for snap rounding's point queries). With across_rings_only, pairs of one ring are left out too
// (ring_of[s] numbers the ring of s; read only on the grid walk).
template <class F>
void for_each_candidate_pair(const std::vector<Segment>& segs, const SegmentIndex& index,
                             SegmentGrid* grid, bool across_rings_only,
                             const std::uint32_t* ring_of, F&& visit) {
  if (grid != nullptr && !grid_walk_is_worse(*grid, index, segs.size())) {
    // Many pairs in the cells, and the index has even more: long near-parallel segments
    // crowding the cells (zigzag stars). Sorting the crowded cells by offset leaves few.
    grid->order_if_crowded(segs);
    grid->for_each_candidate_pair([&](std::uint32_t i, std::uint32_t j) {
      if (across_rings_only && ring_of[i] == ring_of[j]) return;
      if (boxes_overlap(segs[i], segs[j])) visit(i, j);
    });
  } else {
    index.for_each_overlapping_pair(visit, across_rings_only);
  }
}

}  // namespace edgeland::detail
