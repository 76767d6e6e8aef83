#pragma once
// Collinear merging: normalize's defence against stacks of collinear, overlapping edges.
//
// N copies of one square, or N squares shifted along a common side, put N edges on one line
// that all overlap: noding finds N^2 overlapping pairs and cuts each edge at every end point of
// the others, N^2 fragments (4,000 shifted squares took 444 s and 5.7 GB). Under a winding
// fill (normalize, import) an edge stands only for its contribution to the winding number, so
// all the edges of one overlap component (edges of one line, one channel and one polygon tag,
// linked by stretches of positive length they share) can be replaced by the elementary
// intervals between their end points, each carrying the sum of the contributions (its
// weight). The arrangement is the same one noding would build: the same points, the same
// stretches, the same net multiplicity on each; only the segments that make it up differ. The
// pipeline takes this path when noding has counted more overlapping pairs than a budget
// linear in the input (pipeline.cpp), so ordinary inputs are never rebuilt.
//
// Not for the owner labelings (clip on valid sets, relabel): there an edge's polygon matters,
// and in valid operands at most two edges of an operand overlap anywhere anyway.
#include <cstdint>
#include <vector>

#include "input_edges.hpp"

namespace edgeland::detail {

struct MergedEdges {
  EdgeList edges;  // weight filled for every segment
  // Segments whose ring link is broken at either end (next to a merged stretch) and the
  // intervals themselves (each its own one-segment "ring", next[s] == s): the plane graph must
  // treat them as touched, never chain them.
  std::vector<std::uint8_t> unchained;
};

// The edges with every overlap component of two or more edges replaced by its elementary
// intervals (lo -> hi, lexicographically, with the summed weight, possibly 0). The rest of a
// ring whose edges were merged keeps its order, cut into open runs whose last edge's `next`
// points back at the run's first (rings occupy consecutive ids). O(n log n).
MergedEdges merge_collinear_overlaps(const EdgeList& in);

}  // namespace edgeland::detail
