#pragma once
// A splitting cell's content cut into its children's boxes (spatial/README.md, "An edit",
// step 4; the grid of thesis 4.4 is built the same way).
#include <vector>

#include "edgeland/clip/relabel.hpp"
#include "edgeland/kernel/bbox.hpp"

namespace edgeland::detail {

// The parts of `content` (a cell's: the canonical decomposition of its regions, I3) in each of
// `boxes` (split_boxes: closed boxes with disjoint interiors covering the cell), in their order.
// One cut_to_windows() arrangement for all of them, so the pieces on the two sides of a new cell
// line come from the same rounded edges. When the content lies in one child's closed box, that
// child takes it as it is and the others nothing, without an arrangement: cut_to_windows()
// answers exactly that then, each window's part being the canonical decomposition of the regions
// within it (here all of them, whose decomposition the content already is) and the other
// windows meeting the content in no area. A small island filled into a large empty cell makes it
// split level after level until the island straddles a cell line (in a fresh empty world of
// 16384^2, six or seven levels for an island of 100 edges); those levels now cost a box test each
// instead of an arrangement. (Solid rock with a hole spans every child: it is cut as before.)
// Checked mode compares the answer with cut_to_windows()'s (InternalError if they differ).
std::vector<LabeledSet> cut_to_children(LabeledSet content, const std::vector<Box64>& boxes,
                                        const ClipOptions& options);

}  // namespace edgeland::detail
