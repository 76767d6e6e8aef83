// relabel_cell() (relabel.hpp): a landscape cell's overlay, the quick cases first
// (relabel_quick.hpp), then relabel_near()'s arrangement, small (small_overlay.hpp) or general.
#include <vector>

#include "edgeland/clip/relabel.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "relabel_pipeline.hpp"
#include "relabel_quick.hpp"
#include "small_overlay.hpp"

namespace edgeland {
namespace {

using detail::ScratchVector;

std::size_t edges_of(const PolygonSet& set, std::span<const std::uint32_t> members) {
  std::size_t n = 0;
  for (std::uint32_t m : members) n += set[m].size();
  return n;
}

// Whether the arrangement can be the small overlay's: every region edge, the near members' and
// the window's (an upper bound on what relabel_near() puts in).
bool small_enough(const LabeledSet& cell, std::span<const detail::StepNear> steps) {
  std::size_t n = 4;
  for (const detail::StepNear& step : steps)
    n += edges_of(step.shape->polygons(), step.near.members);
  for (const Polygon& p : cell.set.polygons()) n += p.size();
  return n <= detail::kSmallOverlayUpTo;
}

ScratchVector<Box64> boxes_of(const LabeledSet& cell) {
  const PolygonSet& pieces = cell.set.polygons();
  ScratchVector<Box64> boxes;
  boxes.resize(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) boxes[i] = *bounding_box(pieces[i]);
  return boxes;
}

// Checked mode: the overlay is relabel_batch()'s (clip/README.md, "The small overlay" and
// "Regions the shape cannot reach", say why it is).
void require_relabels(const LabeledSet& cell, std::span<const detail::StepNear> steps,
                      const Box64& window, const LabeledSet& got) {
  ScratchVector<RelabelStep> asked;
  for (const detail::StepNear& step : steps) asked.push_back({step.shape, step.table});
  const LabeledClipResult full =
      relabel_batch(cell.set, cell.labels, asked, window, {.checked = true});
  // Not reached by tests: the two agree (an internal error otherwise).
  if (!same_content(full.regions, got))
    throw InternalError("relabel_cell differs from relabel_batch", to_wkt(cell.set.polygons()),
                        to_wkt(steps.front().shape->polygons()));
}

// One arrangement of the cell with up to kMaxBatchSteps steps near it (relabel_near()'s).
CellOverlayResult arrange(const LabeledSet& cell, std::span<const Box64> boxes,
                          std::span<const detail::StepNear> steps, const Box64& window,
                          const ClipOptions& options) {
  CellOverlayResult out;
  const bool small = small_enough(cell, steps);
  out.path = small ? CellOverlayPath::kSmall : CellOverlayPath::kGeneral;
  LabeledClipResult r =
      detail::relabel_near({cell.set, cell.labels, steps, window, options, small}, boxes);
  if (options.checked) require_relabels(cell, steps, window, r.regions);
  out.pieces_left_out = r.pieces_left_out;
  if (!same_content(r.regions, cell)) out.content = std::move(r.regions);
  return out;
}

// Steps past kMaxBatchSteps: one arrangement per kMaxBatchSteps, each on the last one's result.
CellOverlayResult arrange_in_turn(const LabeledSet& cell, std::span<const detail::StepNear> steps,
                                  const Box64& window, const ClipOptions& options) {
  CellOverlayResult out =
      arrange(cell, boxes_of(cell), steps.first(kMaxBatchSteps), window, options);
  for (std::size_t k = kMaxBatchSteps; k < steps.size(); k += kMaxBatchSteps) {
    const LabeledSet now = out.content ? std::move(*out.content) : cell;
    const auto chunk = steps.subspan(k, std::min(kMaxBatchSteps, steps.size() - k));
    CellOverlayResult next = arrange(now, boxes_of(now), chunk, window, options);
    out.path = std::max(out.path, next.path);
    out.pieces_left_out += next.pieces_left_out;
    out.content = next.content ? std::move(next.content) : std::optional<LabeledSet>(now);
  }
  if (out.content && same_content(*out.content, cell)) out.content.reset();
  return out;
}

}  // namespace

CellOverlayResult relabel_cell(const LabeledSet& cell, const ValidSet& shape, const Box64& window,
                               std::span<const RegionLabel> table, const ClipOptions& options) {
  const RelabelStep step{&shape, table};
  return relabel_cell(cell, std::span(&step, 1), window, options);
}

CellOverlayResult relabel_cell(const LabeledSet& cell, std::span<const RelabelStep> steps,
                               const Box64& window, const ClipOptions& options) {
  detail::require_relabel_input(cell.set, cell.labels, window);
  detail::require_shapes(steps);
  const ScratchVector<detail::StepNear> near = detail::steps_near(steps, window);
  if (near.empty()) return {};  // no member near the window: the cell stays as it is
  if (near.size() > kMaxBatchSteps) return arrange_in_turn(cell, near, window, options);
  const ScratchVector<Box64> boxes = boxes_of(cell);
  if (near.size() == 1) {
    const detail::StepNear& step = near.front();
    if (auto quick =
            detail::quick_overlay({cell, boxes, window}, *step.shape, step.near, step.table))
      return {std::move(quick->content), CellOverlayPath::kQuick, 0};
  }
  return arrange(cell, boxes, near, window, options);
}

}  // namespace edgeland
