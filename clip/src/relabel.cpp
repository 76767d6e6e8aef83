// Overlays of labeled regions (relabel.hpp): the pipeline of clip/README.md with a face label
// made of the region below and the shape or window around it.
#include "edgeland/clip/relabel.hpp"

#include <algorithm>

#include "edgeland/kernel/wkt_writer.hpp"
#include "pipeline_builder.hpp"
#include "relabel_pipeline.hpp"
#include "valid_set_factory.hpp"

namespace edgeland {
namespace {

void require_labels(const ValidSet& regions, std::span<const RegionLabel> labels) {
  if (labels.size() != regions.polygons().size())
    throw InvalidOverlay(InvalidOverlay::Reason::kLabelCount, labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (labels[i] == kNoRegion) throw InvalidOverlay(InvalidOverlay::Reason::kZeroLabel, i);
}

// Whether no two of a few boxes have interiors in common (a split's children: four at most),
// compared pairwise; many boxes (or any overlap, to name the window) go to validate().
bool interiors_disjoint(std::span<const Box64> boxes) {
  if (boxes.size() > 16) return false;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (boxes[i].overlaps_open(boxes[j])) return false;
  return true;
}

void require_window(const Box64& w, std::size_t index) {
  if (!in_range(w.min) || !in_range(w.max) || !w.has_interior())
    throw InvalidOverlay(InvalidOverlay::Reason::kBadWindow, index);
}

// The labeled set of a pipeline result (its polygons are an operation's output: valid).
LabeledSet labeled(detail::PipelineResult& r, std::size_t begin, std::size_t end,
                   RegionLabel (*label_of)(detail::FaceLabel)) {
  ClipResult part;
  if (begin == end) {
    // Nothing: the vector is not touched (all of it may have been moved out for a window before).
  } else if (begin == 0 && end == r.clipped.polygons.size()) {
    part.polygons = std::move(r.clipped.polygons);  // all of it: no copy of the vector
  } else {
    part.polygons.assign(
        std::make_move_iterator(r.clipped.polygons.begin() + static_cast<std::ptrdiff_t>(begin)),
        std::make_move_iterator(r.clipped.polygons.begin() + static_cast<std::ptrdiff_t>(end)));
  }
  LabeledSet out{ValidSetFactory::from(std::move(part)).set, {}};
  out.labels.reserve(end - begin);
  for (std::size_t i = begin; i < end; ++i) out.labels.push_back(label_of(r.labels[i]));
  return out;
}

RegionLabel low_half(detail::FaceLabel l) { return static_cast<RegionLabel>(l & 0xffffffff); }
std::size_t high_half(detail::FaceLabel l) { return static_cast<std::size_t>(l >> 32); }

// In checked mode: every output polygon of `set` lies in `window` (InternalError otherwise).
void check_inside(const PolygonSet& set, const Box64& window, const std::string& what,
                  const std::function<std::string()>& inputs) {
  for (const Polygon& p : set)
    if (!window.contains(*bounding_box(p)))  // Not reached by tests: an internal error.
      throw InternalError(what + ": output polygon outside its window", inputs(),
                          to_wkt(PolygonSet{box_ring(window)}));
}

}  // namespace

namespace detail {

void require_relabel_input(const ValidSet& regions, std::span<const RegionLabel> labels,
                           const Box64& window) {
  require_labels(regions, labels);
  require_window(window, 0);
  const PolygonSet& members = regions.polygons();
  for (std::size_t i = 0; i < members.size(); ++i)
    if (!window.contains(*bounding_box(members[i])))
      throw InvalidOverlay(InvalidOverlay::Reason::kOutsideWindow, i);
}

ShapeNearWindow shape_near_window(const ValidSet& shape, const Box64& window) {
  ShapeNearWindow near;
  for (std::uint32_t i = 0; i < shape.polygons().size(); ++i) {
    const Box64 b = *bounding_box(shape.polygons()[i]);
    if (!b.overlaps(window)) continue;
    near.members.push_back(i);
    near.boxes.push_back(b);
    near.all_inside = near.all_inside && window.contains(b);
  }
  return near;
}

namespace {

// The arrangement of a call (relabel_pipeline.hpp): the regions in play (channel 0), each step's
// near members (channel 1; with several steps, step k's edges weighted 4^k) and, when needed,
// the window's ring (with several steps weighted 4^steps), labeled by `label_of`.
PipelineBuilder describe(const RelabelCall& call, const LabelOf& label_of,
                         const std::vector<std::uint32_t>* in_play) {
  const bool batch = call.steps.size() > 1;
  PipelineBuilder p(LabelMode::kOwnerAndCount, label_of, call.options.checked);
  p.subject(call.regions.polygons(), in_play);
  bool collinear_free = ValidSetFactory::collinear_free(call.regions);
  for (std::size_t k = 0; k < call.steps.size(); ++k) {
    const std::size_t from = p.edge_count();
    p.clip(call.steps[k].shape->polygons(), &call.steps[k].near.members);
    if (batch) p.weighted_from(from, std::int32_t{1} << (2 * k));
    collinear_free = collinear_free && ValidSetFactory::collinear_free(*call.steps[k].shape);
  }
  if (call.window_ring()) {
    const std::size_t from = p.edge_count();
    p.clip_box(call.window);
    if (batch) p.weighted_from(from, std::int32_t{1} << (2 * call.steps.size()));
  }
  p.collinear_free(collinear_free).corner_bridges().small_overlay(call.small);
  return p;
}

}  // namespace

PipelineResult run_relabel(const RelabelCall& call, const std::vector<std::uint32_t>* in_play,
                           std::vector<Box64>* moved) {
  const PolygonSet& members = call.regions.polygons();
  const Box64& window = call.window;
  // One step: when all its near members lie in the window, being inside one of them is being
  // inside shape ∩ window and the window's own ring is not needed; otherwise it joins them and
  // "inside both" is a count of two. Several: BatchTable (face_label.hpp).
  const StepNear& first = call.steps.front();
  const RelabelTable one{call.labels.data(), first.table.data(), first.table.size(),
                         call.window_ring() ? 2 : 1};
  ScratchVector<std::span<const RegionLabel>> tables;
  for (const StepNear& step : call.steps) tables.push_back(step.table);
  const BatchTable several{call.labels.data(), tables.data(),
                           static_cast<std::uint32_t>(tables.size()), call.window_ring()};
  const LabelOf label_of = tables.size() > 1 ? LabelOf::batch(&several) : LabelOf::relabel(one);
  // The two lambdas are called, and the unwinding of the builder below runs, only for an
  // internal error: not reached by tests.
  auto inputs = [&] { return to_wkt(members); };
  auto shape_wkt = [&] {
    std::string text;
    for (const StepNear& step : call.steps) text += to_wkt(step.shape->polygons()) + " ";
    return text + "within " + to_wkt(PolygonSet{box_ring(window)});
  };
  PipelineResult r = guarded([&] { return describe(call, label_of, in_play).run(moved, true); },
                             call.options, "relabel", inputs, shape_wkt);
  if (call.options.checked) check_inside(r.clipped.polygons, window, "relabel", inputs);
  return r;
}

LabeledClipResult relabeled_regions(PipelineResult& r) {
  LabeledClipResult out;
  out.stats = r.clipped.stats;
  out.regions = labeled(r, 0, r.clipped.polygons.size(), low_half);
  return out;
}

}  // namespace detail

LabeledClipResult relabel(const ValidSet& regions, std::span<const RegionLabel> labels,
                          const ValidSet& shape, const Box64& window,
                          std::span<const RegionLabel> table, const ClipOptions& options) {
  detail::require_relabel_input(regions, labels, window);
  const detail::StepNear step{&shape, table, detail::shape_near_window(shape, window)};
  detail::PipelineResult r = detail::run_relabel(
      {regions, labels, std::span(&step, 1), window, options}, nullptr, nullptr);
  return detail::relabeled_regions(r);
}

std::vector<LabeledSet> cut_to_windows(const ValidSet& regions, std::span<const RegionLabel> labels,
                                       std::span<const Box64> windows, const ClipOptions& options) {
  require_labels(regions, labels);
  for (std::size_t i = 0; i < windows.size(); ++i) require_window(windows[i], i);
  auto window_rings = [&] {
    PolygonSet rings;
    for (const Box64& w : windows) rings.push_back(box_ring(w));
    return rings;
  };
  if (!interiors_disjoint(windows)) {
    const ValidationReport disjoint = validate(window_rings(), 1);  // names the window
    if (!disjoint.ok())
      throw InvalidOverlay(InvalidOverlay::Reason::kWindowsOverlap,
                           disjoint.violations.front().polygon);
  }
  const PolygonSet& members = regions.polygons();
  // As in relabel(): the lambdas and the unwinding of the builder below run only for an
  // internal error, not reached by tests.
  auto inputs = [&] { return to_wkt(members); };
  auto windows_wkt = [&] { return to_wkt(window_rings()); };
  detail::PipelineResult r = detail::guarded(
      [&] {
        detail::PipelineBuilder p(detail::LabelMode::kOwner,
                                  detail::LabelOf::windows(labels.data()), options.checked);
        p.subject(members);
        for (std::size_t k = 0; k < windows.size(); ++k)
          p.clip_box(windows[k], static_cast<std::int32_t>(k));
        return p.collinear_free(ValidSetFactory::collinear_free(regions))
            .corner_bridges()
            .small_overlay(true)
            .run(nullptr, true);
      },
      options, "cut_to_windows", inputs, windows_wkt);
  // Stable partition by window keeps each window's polygons in canonical order.
  std::vector<std::size_t> order(r.labels.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return high_half(r.labels[a]) < high_half(r.labels[b]);
  });
  detail::PipelineResult sorted;
  sorted.clipped.stats = r.clipped.stats;
  for (std::size_t i : order) {
    sorted.clipped.polygons.push_back(std::move(r.clipped.polygons[i]));
    sorted.labels.push_back(r.labels[i]);
  }
  std::vector<LabeledSet> out;
  std::size_t begin = 0;
  for (std::size_t w = 0; w < windows.size(); ++w) {
    std::size_t end = begin;
    while (end < sorted.labels.size() && high_half(sorted.labels[end]) == w) ++end;
    if (options.checked && begin < end) {
      // gcov ascribes the unwinding of `part` (an internal error) to the next line: not
      // reached by tests.
      const PolygonSet part(sorted.clipped.polygons.begin() + static_cast<std::ptrdiff_t>(begin),
                            sorted.clipped.polygons.begin() + static_cast<std::ptrdiff_t>(end));
      check_inside(part, windows[w], "cut_to_windows", inputs);
    }
    out.push_back(labeled(sorted, begin, end, low_half));
    begin = end;
  }
  return out;
}

}  // namespace edgeland
