#pragma once
// Overlays of labeled regions: the clipper's operations on a partition of the plane into
// regions of several kinds (materials), in one arrangement, so that the boundaries between
// regions are shared edges of one snap-rounded graph and no two regions can overlap afterwards.
// This is what the landscape's edits (spatial/README.md) are made of: applying `fill` as a
// difference on every other material and a union on one would round each material's copy of
// the shape's boundary on its own, and the copies could cross.
//
// A LABELED SET is a valid polygon set (clip.hpp ValidSet) whose members carry labels > 0; the
// region of label l is the union of its members. Label 0 stands for the uncovered plane.
//
// CANONICAL DECOMPOSITION. Every result holds, for each label, its region cut into maximal
// hole-free polygons: faces of one label are merged (members touching along an edge become one
// polygon; members touching at a vertex stay apart, as a strictly simple polygon must), and a
// region with holes is cut by bridges between its corner vertices (and the points where two of
// its boundary rings touch) by the rule of clip/README.md "Hole splitting". So the output is a
// function of the labeled regions alone: equal regions give byte-identical results, whatever
// polygons described them. Polygons are in clip.hpp's canonical form and order; labels follow.
//
// ACCURACY, LOCALITY, ERRORS, MEMORY, THREADS: as for clip() (clip.hpp), the exact result being
// the relabeled regions.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "edgeland/clip/errors.hpp"
#include "edgeland/clip/types.hpp"
#include "edgeland/clip/valid_set.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/export.hpp"

namespace edgeland {

using RegionLabel = std::uint32_t;
inline constexpr RegionLabel kNoRegion = 0;

// A valid set with a label per member: labels[i] > 0 labels set.polygons()[i].
struct LabeledSet {
  ValidSet set;
  std::vector<RegionLabel> labels;
};

struct LabeledClipResult {
  LabeledSet regions;
  ClipStats stats;
  std::size_t pieces_left_out = 0;  // relabel_near(): input pieces returned as they were
};

// Inside shape ∩ window, a point of label l becomes table[l] (l = 0: a point no member covers;
// table[l] = 0 removes it; labels l >= table.size() are kept); elsewhere in the window labels
// are kept. Every member of `regions` must lie in the window (closed box): the result lies in it.
// One arrangement of regions, shape and window, rounded once: cutting the shape to the window
// and applying it happen in the same snap rounding. An empty shape relabels nothing and
// returns the canonical decomposition of `regions` (and rounds nothing: no two members cross).
// O((n + k) log n) as clip() for n vertices (shape members that cannot reach the window are left
// out first) and k crossings. Throws InvalidOverlay; InternalError as clip().
EDGELAND_EXPORT LabeledClipResult relabel(const ValidSet& regions,
                                          std::span<const RegionLabel> labels,
                                          const ValidSet& shape, const Box64& window,
                                          std::span<const RegionLabel> table,
                                          const ClipOptions& options = {});

// relabel() of regions that already are a canonical decomposition (an earlier relabel() or
// cut_to_windows() result with its labels, as a landscape cell holds), with the regions the
// shape cannot reach left out of the arrangement and returned as they are: the cost follows
// the regions the shape and its rounding reach, not all of them. A region is left out when its
// box, grown by a unit, meets no box of a shape member reaching the window nor of any segment
// snap rounding moved (otherwise the overlay runs again on every region, as relabel(): at most
// two runs); the pieces of one label whose boxes meet go in or stay out together. On such input
// the result is relabel()'s, byte for byte (clip/README.md, "Regions the shape cannot reach");
// on other input it is still valid and labels every point as relabel() does, but left-out
// regions keep the pieces they were given.
// The stats count what the arrangement that ran met (left-out regions add nothing). Errors as
// relabel().
EDGELAND_EXPORT LabeledClipResult relabel_near(const ValidSet& regions,
                                               std::span<const RegionLabel> labels,
                                               const ValidSet& shape, const Box64& window,
                                               std::span<const RegionLabel> table,
                                               const ClipOptions& options = {});

// The regions cut into closed boxes with pairwise disjoint interiors, one labeled set per window,
// from one arrangement of the regions and all windows: along a line two windows share, the
// pieces on both sides come from the same rounded edges, so they meet exactly. Parts outside
// every window are dropped. O((n + k) log n). Throws InvalidOverlay; InternalError as clip().
EDGELAND_EXPORT std::vector<LabeledSet> cut_to_windows(const ValidSet& regions,
                                                       std::span<const RegionLabel> labels,
                                                       std::span<const Box64> windows,
                                                       const ClipOptions& options = {});

}  // namespace edgeland
