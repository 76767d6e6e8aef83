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
// A flat index (few segments) is never worth a grid.
inline bool runs_are_short(const SegmentIndex& index, std::size_t segments) {
  constexpr std::size_t kGridWalkFrom = 64;                   // segments
  constexpr std::size_t kGridWalkBelowRunLengthX16 = 16 * 3;  // runs shorter than 3 segments
  return segments >= kGridWalkFrom && !index.flat() &&
         index.run_length_x16() < kGridWalkBelowRunLengthX16;
}

// Whether to walk `grid` rather than the run index, by the pairs each would propose; only
// counted when the grid's cells hold many (more than 16 per segment). A grid sized for spikes
// fails on long parallel segments side by side (comb teeth 10^8 long and 80 apart: 10^4 of
// them per cell), whose runs' x-ranges barely overlap: a cheap index is taken at once. Else the
// grid's crowded cells are ordered (segment_grid.hpp: long near-parallel segments, as in zigzag
// stars, leave few pairs then) and the two counts compared again.
inline bool walk_grid(SegmentGrid& grid, const SegmentIndex& index,
                      const std::vector<Segment>& segs) {
  const std::size_t many = 16 * segs.size() + 4096;
  const std::size_t cell_pairs = grid.cell_pairs();
  if (cell_pairs <= many) return true;
  const std::size_t index_pairs = index.x_overlapping_run_pairs(cell_pairs);
  if (index_pairs <= many) return false;
  // Only the count is needed now: the runs go before the grid grows by its offset bounds
  // (rebuilt should the index win after all), so the two are never held together.
  index.release_runs();
  grid.order_crowded_cells(segs);
  return grid.cell_pairs() <= index_pairs;
}

// visit(i, j) once for every pair of `segs` whose closed boxes overlap, except consecutive
// segments of one monotone run of the index (they meet only at their common end): through
// `grid` when given (a SegmentGrid of segs, possibly left ordered for snap rounding's point
// queries) and chosen by walk_grid, else through the index. With across_rings_only, pairs of
// one ring are left out too (ring_of[s] numbers the ring of s; read only on the grid walk).
template <class F>
void for_each_candidate_pair(const std::vector<Segment>& segs, const SegmentIndex& index,
                             SegmentGrid* grid, bool across_rings_only,
                             const std::uint32_t* ring_of, F&& visit) {
  if (grid != nullptr && walk_grid(*grid, index, segs)) {
    index.release_runs();  // counted only; rebuilt should snap rounding query the index
    grid->for_each_candidate_pair([&](std::uint32_t i, std::uint32_t j) {
      if (across_rings_only && ring_of[i] == ring_of[j]) return;
      if (boxes_overlap(segs[i], segs[j])) visit(i, j);
    });
  } else {
    index.for_each_overlapping_pair(visit, across_rings_only);
  }
}

}  // namespace edgeland::detail
