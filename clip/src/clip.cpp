// The public operations of clip.hpp, each a short call into what does the work: the validating
// clip() (validating_clip.hpp), the locality filter (clip_near.hpp), the box path
// (box_clip.hpp), OGC import (ogc_import.hpp) and the pipeline itself (pipeline_builder.hpp).
#include "edgeland/clip/clip.hpp"

#include <string>

#include "box_clip.hpp"
#include "clip_near.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "ogc_import.hpp"
#include "pipeline_builder.hpp"
#include "valid_set_factory.hpp"
#include "validating_clip.hpp"

namespace edgeland {

ClipResult clip(ClipOp op, const PolygonSet& subject, const PolygonSet& clip_set,
                const ClipOptions& options) {
  return detail::validating_clip(op, subject, clip_set, options);
}

ValidClipResult clip(ClipOp op, const ValidSet& subject, const ValidSet& clip_set,
                     const ClipOptions& options) {
  return ValidSetFactory::from(detail::clip_of_valid(
      op, subject.polygons(), clip_set.polygons(), options, ValidSetFactory::canonical(subject),
      ValidSetFactory::collinear_free(subject) && ValidSetFactory::collinear_free(clip_set)));
}

ValidClipResult clip_to_box(const ValidSet& set, const Box64& box, const ClipOptions& options) {
  detail::require_valid_box(box);
  return ValidSetFactory::from(detail::clip_valid_to_box(set.polygons(), box, options,
                                                         ValidSetFactory::collinear_free(set)));
}

ClipResult clip_to_box(const PolygonSet& set, const Box64& box, const ClipOptions& options) {
  detail::require_valid_box(box);
  detail::require_valid(set, Operand::kSubject);
  return detail::clip_valid_to_box(set, box, options, false);
}

ClipResult normalize(const std::vector<Ring>& rings, FillRule rule, const ClipOptions& options) {
  for (std::size_t r = 0; r < rings.size(); ++r)
    for (std::size_t i = 0; i < rings[r].size(); ++i)
      if (!in_range(rings[r][i])) throw CoordinateOutOfRange(Operand::kRings, r, 0, i, rings[r][i]);
  // gcov ascribes the unwinding of the builder below, run only when the pipeline throws, to the
  // `[&] {` line, and the WKT lambda below is called only then (an internal error): not reached
  // by tests.
  return detail::guarded(
      [&] {
        return detail::PipelineBuilder(detail::LabelMode::kWinding, detail::LabelOf::fill(rule),
                                       options.checked)
            .winding_rings(rings)
            .clipped();
      },
      options, std::string("normalize ") + fill_rule_name(rule),
      [&] {
        PolygonSet as_set(rings.begin(), rings.end());
        return to_wkt(as_set);
      },
      [] { return std::string("MULTIPOLYGON EMPTY"); });
}

ClipResult import_polygons(const std::vector<std::vector<Ring>>& polygons,
                           const ClipOptions& options) {
  return detail::import_ogc(polygons, options);
}

ValidClipResult normalize_to_valid_set(const std::vector<Ring>& rings, FillRule rule,
                                       const ClipOptions& options) {
  return ValidSetFactory::from(normalize(rings, rule, options));
}

ValidClipResult import_to_valid_set(const std::vector<std::vector<Ring>>& polygons,
                                    const ClipOptions& options) {
  return ValidSetFactory::from(import_polygons(polygons, options));
}

// The members of a valid set have disjoint interiors and turn counter-clockwise, so the
// positive fill of their rings is exactly their union.
ValidClipResult merge(const ValidSet& set, const ClipOptions& options) {
  const PolygonSet& members = set.polygons();
  return normalize_to_valid_set(std::vector<Ring>(members.begin(), members.end()),
                                FillRule::kPositive, options);
}

}  // namespace edgeland
