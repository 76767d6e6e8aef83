// clip_to_box() through the pipeline (box_clip.hpp).
#include "box_clip.hpp"

#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "pipeline_builder.hpp"

namespace edgeland::detail {

void require_valid_box(const Box64& box) {
  for (const Point64 corner : {box.min, box.max})
    if (!in_range(corner)) throw CoordinateOutOfRange(Operand::kClip, 0, 0, kNone, corner);
  if (box.min.x > box.max.x || box.min.y > box.max.y) throw InvalidBox(Operand::kClip, box);
}

ClipResult clip_valid_to_box(const PolygonSet& set, const Box64& box, const ClipOptions& options,
                             bool collinear_free) {
  if (!box.has_interior()) return {};  // a valid box: min <= max
  // Members that cannot reach the box take no part; the rest go through the full pipeline,
  // so the result stays closed under repetition exactly like clip().
  std::vector<std::uint32_t> near;
  for (std::uint32_t i = 0; i < set.size(); ++i)
    if (bounding_box(set[i])->overlaps(box)) near.push_back(i);
  const PolygonSet cell{box_ring(box)};
  // gcov ascribes the unwinding of the builder below, run only when the pipeline throws (an
  // internal error), to the `[&] {` line: not reached by tests.
  return guarded(
      [&] {
        return PipelineBuilder(LabelMode::kOwner, LabelOf::operation(ClipOp::kIntersection),
                               options.checked)
            .subject(set, &near)
            .clip(cell)
            .collinear_free(collinear_free)
            .clipped();
      },
      options, "clip_to_box", [&] { return to_wkt(set); }, [&] { return to_wkt(cell); });
}

}  // namespace edgeland::detail
