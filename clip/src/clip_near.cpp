// The locality filter of clip() (clip_near.hpp).
#include "clip_near.hpp"

#include <algorithm>

#include "box_sweep.hpp"
#include "canonical.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "grown_box.hpp"
#include "pipeline_builder.hpp"

namespace edgeland::detail {
namespace {

// Which subject polygons (by their boxes) come within a unit of the clip operand's box.
std::vector<bool> near_clip_operand(const std::vector<Box64>& boxes, const PolygonSet& clip_set) {
  std::vector<bool> included(boxes.size(), false);
  if (const auto cb = bounding_box(clip_set)) {
    const Box64 reach = grown(*cb, 1);
    for (std::size_t i = 0; i < boxes.size(); ++i) included[i] = boxes[i].overlaps(reach);
  }
  return included;
}

// The operation on the included subject polygons and the whole clip operand; `moved` receives
// the boxes of the segments snap rounding moved.
ClipResult clip_included(ClipOp op, const PolygonSet& subject, const PolygonSet& clip_set,
                         const std::vector<bool>& included, bool collinear_free, bool check_stages,
                         Screening* screening, std::vector<Box64>& moved) {
  std::vector<std::uint32_t> near;
  for (std::uint32_t i = 0; i < subject.size(); ++i)
    if (included[i]) near.push_back(i);
  return PipelineBuilder(LabelMode::kOwner, LabelOf::operation(op), check_stages)
      .subject(subject, &near)
      .clip(clip_set)
      .collinear_free(collinear_free)
      .screened_by(screening)
      .clipped(&moved);
}

// Brings in every left-out polygon whose box, grown by a unit, meets the box of a moved
// segment. Returns whether any was.
bool include_near_moved(const std::vector<Box64>& boxes, const std::vector<Box64>& moved,
                        std::vector<bool>& included) {
  std::vector<Box64> left_out;
  std::vector<std::size_t> left_out_index;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    if (!included[i]) {
      left_out.push_back(grown(boxes[i], 1));
      left_out_index.push_back(i);
    }
  bool grew = false;
  for_each_overlapping_pair(left_out, moved, [&](std::uint32_t k, std::uint32_t) {
    if (!included[left_out_index[k]]) included[left_out_index[k]] = grew = true;
  });
  return grew;
}

// Adds the left-out subject polygons to the computed result, keeping canonical order.
void add_left_out(ClipResult& r, const PolygonSet& subject, const std::vector<bool>& included,
                  bool subject_canonical) {
  const auto computed = static_cast<std::ptrdiff_t>(r.polygons.size());
  for (std::size_t i = 0; i < subject.size(); ++i)
    if (!included[i])
      r.polygons.push_back(subject_canonical ? subject[i] : canonical_ring(subject[i]));
  // The computed part is sorted; so are the left-out polygons of a canonical subject, and
  // otherwise they are sorted alone (usually a few) before the two parts are merged.
  if (!subject_canonical) std::sort(r.polygons.begin() + computed, r.polygons.end());
  std::inplace_merge(r.polygons.begin(), r.polygons.begin() + computed, r.polygons.end());
}

}  // namespace

ClipResult clip_near(ClipOp op, const PolygonSet& subject, const PolygonSet& clip_set,
                     bool subject_canonical, bool collinear_free, bool check_stages,
                     Screening* screening) {
  std::vector<Box64> boxes(subject.size());
  for (std::size_t i = 0; i < subject.size(); ++i) boxes[i] = *bounding_box(subject[i]);
  std::vector<bool> included = near_clip_operand(boxes, clip_set);
  // Left-out subject polygons never reach the pipeline, so its checks cannot vouch for them.
  if (screening && std::find(included.begin(), included.end(), false) != included.end())
    screening->validate_in_full(Operand::kSubject);
  for (;;) {
    std::vector<Box64> moved;
    ClipResult r = clip_included(op, subject, clip_set, included, collinear_free, check_stages,
                                 screening, moved);
    if (screening && screening->suspect) return r;
    if (include_near_moved(boxes, moved, included)) continue;
    if (op != ClipOp::kIntersection) add_left_out(r, subject, included, subject_canonical);
    return r;
  }
}

ClipResult clip_of_valid(ClipOp op, const PolygonSet& subject, const PolygonSet& clip_set,
                         const ClipOptions& options, bool subject_canonical, bool collinear_free) {
  return guarded(
      [&] {
        return clip_near(op, subject, clip_set, subject_canonical, collinear_free, options.checked);
      },
      options, op_name(op), [&] { return to_wkt(subject); }, [&] { return to_wkt(clip_set); });
}

}  // namespace edgeland::detail
