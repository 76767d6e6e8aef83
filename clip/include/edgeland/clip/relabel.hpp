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
#include <optional>
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

// The same content: equal polygons in the same order, with equal labels.
inline bool same_content(const LabeledSet& a, const LabeledSet& b) {
  return a.labels == b.labels && a.set.polygons() == b.set.polygons();
}

struct LabeledClipResult {
  LabeledSet regions;
  ClipStats stats;
  std::size_t pieces_left_out = 0;  // relabel_near(): input pieces returned as they were
};

// One step of a batch overlay: inside `shape`, a point of label l becomes table[l] (as relabel()).
struct RelabelStep {
  const ValidSet* shape = nullptr;
  std::span<const RegionLabel> table;
};

// Steps one batch overlay takes in one arrangement; relabel_cell() applies more in further
// overlays of this many.
inline constexpr std::size_t kMaxBatchSteps = 14;

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

// How relabel_cell() found its answer.
enum class CellOverlayPath : std::uint8_t {
  kQuick,    // a quick case: box and point tests, no arrangement
  kSmall,    // the small overlay's arrangement (clip/README.md, "The small overlay")
  kGeneral,  // the general pipeline's (more segments than the small overlay takes)
};

struct CellOverlayResult {
  // The cell's content after the overlay; nullopt when it is the cell's content as it was.
  std::optional<LabeledSet> content;
  CellOverlayPath path = CellOverlayPath::kQuick;
  std::size_t pieces_left_out = 0;  // as relabel_near()'s
};

// The overlay of one landscape cell, built for a cell's size: relabel_near() of `cell` (a
// canonical decomposition lying in `window`, as relabel_near() requires) with the shape, whose
// result is relabel()'s byte for byte, found the cheapest way there is. First the quick cases:
// no member near the window, an empty cell kept empty, a member covering the window, a shape
// clear of every boundary or passing only through regions it keeps; each is answered by box,
// point and segment tests with relabel()'s result. Else the arrangement of relabel_near(): up to
// a few hundred segments (a cell of edge_cap edges and a shape of tens) by the small overlay,
// whose noding and snap rounding compare ring and segment boxes and scan for hot pixels, with
// no search structure set up and no allocation but the result's once warm; more by the general
// pipeline. In checked mode every answer that needed an arrangement is compared with relabel()'s
// (InternalError if they differ). Errors as relabel().
EDGELAND_EXPORT CellOverlayResult relabel_cell(const LabeledSet& cell, const ValidSet& shape,
                                               const Box64& window,
                                               std::span<const RegionLabel> table,
                                               const ClipOptions& options = {});
// The same for a batch: relabel_batch() of the cell, the steps whose shapes reach the window in
// one arrangement (kMaxBatchSteps at a time; more in further overlays, each rounded once), with
// relabel_batch()'s result bit for bit. The quick cases answer when at most one step reaches
// the window (that is relabel_cell() of that step). Checked mode compares every arrangement
// with relabel_batch()'s.
EDGELAND_EXPORT CellOverlayResult relabel_cell(const LabeledSet& cell,
                                               std::span<const RelabelStep> steps,
                                               const Box64& window,
                                               const ClipOptions& options = {});

// The steps applied in order in ONE arrangement of the regions, every step's shape and the
// window, rounded once: inside the window a point of label l becomes the label l passed through
// the table of every step whose shape holds it, in order (a point of no region has label 0).
// The exact result is that of relabel() applied step by step; the result differs from the
// step-by-step one only by snap rounding, done once here where steps in turn round each shape
// and again every boundary a later shape passes near (clip/README.md, "Batch overlays").
// One step is relabel(), bit for bit. Throws InvalidOverlay (also kTooManySteps past
// kMaxBatchSteps, kNoShape for a step without a shape); InternalError as clip().
EDGELAND_EXPORT LabeledClipResult relabel_batch(const ValidSet& regions,
                                                std::span<const RegionLabel> labels,
                                                std::span<const RelabelStep> steps,
                                                const Box64& window,
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
