// Batch overlays (relabel.hpp, relabel_batch): several shapes and their tables in one
// arrangement (clip/README.md, "Batch overlays"), and what every overlay call shares about its
// steps.
#include "edgeland/clip/relabel.hpp"
#include "relabel_pipeline.hpp"

namespace edgeland {
namespace detail {

ScratchVector<StepNear> steps_near(std::span<const RelabelStep> steps, const Box64& window) {
  ScratchVector<StepNear> out;
  for (const RelabelStep& step : steps) {
    ShapeNearWindow near = shape_near_window(*step.shape, window);
    if (!near.members.empty()) out.push_back({step.shape, step.table, std::move(near)});
  }
  return out;
}

bool RelabelCall::window_ring() const {
  for (const StepNear& step : steps)
    if (!step.near.all_inside) return true;
  return false;
}

ScratchVector<Box64> RelabelCall::member_boxes() const {
  ScratchVector<Box64> boxes;
  for (const StepNear& step : steps)
    boxes.insert(boxes.end(), step.near.boxes.begin(), step.near.boxes.end());
  return boxes;
}

void require_shapes(std::span<const RelabelStep> steps) {
  for (std::size_t k = 0; k < steps.size(); ++k)
    if (!steps[k].shape) throw InvalidOverlay(InvalidOverlay::Reason::kNoShape, k);
}

}  // namespace detail

LabeledClipResult relabel_batch(const ValidSet& regions, std::span<const RegionLabel> labels,
                                std::span<const RelabelStep> steps, const Box64& window,
                                const ClipOptions& options) {
  detail::require_relabel_input(regions, labels, window);
  if (steps.size() > kMaxBatchSteps)
    throw InvalidOverlay(InvalidOverlay::Reason::kTooManySteps, steps.size());
  detail::require_shapes(steps);
  const detail::ScratchVector<detail::StepNear> near = detail::steps_near(steps, window);
  // No step reaches the window: relabel() with no shape, the regions' canonical decomposition.
  if (near.empty()) return relabel(regions, labels, ValidSet(), window, {}, options);
  detail::PipelineResult r =
      detail::run_relabel({regions, labels, near, window, options}, nullptr, nullptr);
  return detail::relabeled_regions(r);
}

}  // namespace edgeland
