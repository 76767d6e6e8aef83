// run(): the stages of clip/README.md in order, each handing its typed result to the next.
#include "pipeline.hpp"

#include <limits>

#include "assembly.hpp"
#include "canonical.hpp"
#include "collinear_merge.hpp"
#include "hole_splitting.hpp"
#include "snap_rounding.hpp"

namespace edgeland::detail {

void require_valid(const PolygonSet& set, Operand which) {
  const ValidationReport report = validate(set, 1);
  if (!report.ok()) throw_invalid_input(which, report.violations.front());
}

namespace {

// Screening after snap rounding: whether to go on, and whether labeling checks single cover.
// Returns false when noding found an operand invalid (the caller validates in full).
bool screen_after_snap(Screening& screen, const SnapStats& snap, bool& check_cover) {
  if (snap.operand_invalid) {
    screen.suspect = true;
    return false;
  }
  if (snap.hot_pixels > 0) {  // moved: labeling's check would not be exact
    for (int c = 0; c < 2; ++c)
      if (screen.unchecked_multi_ring(c)) screen.validate_in_full(c);
  }
  check_cover = screen.unchecked_multi_ring(0) || screen.unchecked_multi_ring(1);
  return true;
}

// Holed regions cut into hole-free pieces, appended in canonical form with their label.
void split_holed_regions(std::vector<RegionRings>& holed, PipelineResult& out) {
  for (RegionRings& region : holed) {
    for (Ring& r : split_holes(std::move(region.outers), std::move(region.holes),
                               out.clipped.stats.holes_split)) {
      out.clipped.polygons.push_back(canonical_ring(std::move(r)));
      out.labels.push_back(region.label);
    }
  }
}

// More pairs overlapping along a stretch than any ordinary input has (valid sets: about one
// per edge): a stack of collinear edges (collinear_merge.hpp), when merging them is allowed.
std::size_t overlap_budget(const Pipeline& p) {
  if (p.mode != LabelMode::kWinding) return std::numeric_limits<std::size_t>::max();
  return p.overlap_budget.value_or(4 * p.edges.size() + 4096);
}

}  // namespace

PipelineResult run(const Pipeline& p, std::vector<Box64>* moved_boxes, bool with_labels) {
  PipelineResult out;
  SnapStats snap;
  const EdgeList* edges = &p.edges;
  auto fragments = snap_round(edges->segments, edges->next, p.simple_rings, snap,
                              p.screening ? &edges->channel : nullptr, overlap_budget(p));
  MergedEdges merged;
  if (snap.overlap_heavy) {  // noded again without the stacks
    merged = merge_collinear_overlaps(p.edges);
    edges = &merged.edges;
    fragments = snap_round(edges->segments, edges->next, p.simple_rings, snap);
    for (std::size_t s = 0; s < edges->size(); ++s)
      if (merged.unchained[s]) snap.touched[s] = true;
  }
  // The graph and the labels reuse per-thread storage (recycled_vector.hpp says why).
  Reused<PlaneGraph> graph;
  Reused<std::vector<SideState>> labels;
  PlaneGraph& g = *graph;
  std::vector<SideState>& left = *labels;
  bool check_cover = false;
  if (p.screening && !screen_after_snap(*p.screening, snap, check_cover)) return out;
  build_plane_graph(*edges, fragments, snap.touched, g);
  if (!label_sides(g, p.mode, left, check_cover)) {
    p.screening->suspect = true;
    return out;
  }
  Assembled assembled = assemble(g, left, p.label_of, p.collinear_free_operands,
                                 p.corner_bridges);
  out.clipped.polygons = std::move(assembled.rings);  // canonical rings
  out.labels = std::move(assembled.labels);
  split_holed_regions(assembled.holed, out);
  sort_canonical(out.clipped.polygons, with_labels ? &out.labels : nullptr);
  if (!with_labels) out.labels.clear();
  out.clipped.stats.intersections = snap.intersections;
  out.clipped.stats.vertices_snapped = snap.hot_pixels;
  out.clipped.stats.zero_area_dropped = g.cancelled_edges;
  if (moved_boxes) *moved_boxes = std::move(snap.moved_boxes);
  return out;
}

}  // namespace edgeland::detail
