#pragma once
// What relabel() and relabel_near() (relabel.hpp) share: the checks of their input, the shape's
// members that can reach the window, and the pipeline of one labeled overlay.
#include <cstdint>
#include <span>
#include <vector>

#include "edgeland/clip/relabel.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "pipeline.hpp"

namespace edgeland::detail {

// Throws InvalidOverlay unless every region has a label > 0, the window is a box of the input
// range with an interior, and every region lies in it.
void require_relabel_input(const ValidSet& regions, std::span<const RegionLabel> labels,
                           const Box64& window);

// The shape's members whose boxes meet the window (the others take no part) and whether all of
// them lie in it (then the window's own ring is not needed).
struct ShapeNearWindow {
  ScratchVector<std::uint32_t> members;
  ScratchVector<Box64> boxes;  // per entry of `members`
  bool all_inside = true;
};
ShapeNearWindow shape_near_window(const ValidSet& shape, const Box64& window);

// One step of an overlay: a shape, its members near the window, and its table.
struct StepNear {
  const ValidSet* shape = nullptr;
  std::span<const RegionLabel> table;
  ShapeNearWindow near;
};

// The steps whose shapes have members near the window, in order (the others change nothing
// there).
ScratchVector<StepNear> steps_near(std::span<const RelabelStep> steps, const Box64& window);

// Throws InvalidOverlay (kNoShape) unless every step has a shape.
void require_shapes(std::span<const RelabelStep> steps);

// One labeled overlay as relabel(), relabel_batch() and relabel_near() are asked for it: one
// step (relabel's arrangement and face label) or up to kMaxBatchSteps (relabel_batch's).
// `small`: few segments take the small overlay's noding and snap rounding (small_overlay.hpp),
// with the same result.
struct RelabelCall {
  const ValidSet& regions;
  std::span<const RegionLabel> labels;
  std::span<const StepNear> steps;
  const Box64& window;
  const ClipOptions& options;
  bool small = false;
  // Whether some near member reaches past the window: then its ring joins the arrangement.
  bool window_ring() const;
  // The boxes of every step's near members.
  ScratchVector<Box64> member_boxes() const;
};

// The arrangement of the region polygons listed in `in_play` (all of them when null), the
// shape's near members and, when needed, the window's ring; faces relabeled by `table`, regions
// cut at their corners (clip/README.md, "Labeled overlays"). `moved` (if not null) receives the
// boxes of the segments snap rounding moved. Guarded: an internal failure is an InternalError.
PipelineResult run_relabel(const RelabelCall& call, const std::vector<std::uint32_t>* in_play,
                           std::vector<Box64>* moved);

// relabel_near() (relabel.hpp) of a checked call, the pieces' boxes given (a landscape cell keeps
// them).
LabeledClipResult relabel_near(const RelabelCall& call, std::span<const Box64> piece_boxes);

// The labeled regions of a run_relabel() result.
LabeledClipResult relabeled_regions(PipelineResult& r);

}  // namespace edgeland::detail
