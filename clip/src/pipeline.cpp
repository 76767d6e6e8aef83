// run(): the stages of clip/README.md in order, each handing its typed result to the next.
#include "pipeline.hpp"

#include <limits>
#include <optional>
#include <utility>

#include "assembly.hpp"
#include "canonical.hpp"
#include "collinear_merge.hpp"
#include "hole_splitting.hpp"
#include "small_overlay.hpp"
#include "snap_rounding.hpp"
#include "stage_checks.hpp"

namespace edgeland::detail {

void require_valid(const PolygonSet& set, Operand which) {
  const ValidationReport report = validate(set, 1);
  if (!report.ok()) throw_invalid_input(which, report.violations.front());
}

namespace {

// The contacts and fragments of one edge list (noding.hpp, snap_rounding.hpp). Snap rounding
// runs only when noding did not stop.
struct Noded {
  Contacts contacts;
  Snapped snapped;
};

Noded node(const EdgeList& edges, const NodingOptions& options) {
  SegmentSearch search(edges.segments, edges.next);
  Noded n{find_contacts(edges.segments, edges.next, search, options), {}};
  if (n.contacts.stopped()) return n;
  n.snapped = snap_round(edges.segments, edges.next, n.contacts, search);
  // The fragments hold what the contacts said; only their counts and flags are read later.
  discard(n.contacts.splits);
  discard(n.contacts.hot);
  return n;
}

// More pairs overlapping along a stretch than any ordinary input has (valid sets: about one
// per edge): a stack of collinear edges (collinear_merge.hpp), when merging them is allowed.
std::size_t overlap_budget(const Pipeline& p) {
  if (p.mode != LabelMode::kWinding) return std::numeric_limits<std::size_t>::max();
  return p.overlap_budget.value_or(4 * p.edges.size() + 4096);
}

// Whether the small overlay's noding and snap rounding take the edge list (small_overlay.hpp):
// asked for, and few segments of validated rings labeled by owners (weights, a batch overlay's,
// play no part in noding and snap rounding).
bool small_arrangement(const Pipeline& p) {
  return p.small_overlay && p.edges.size() <= kSmallOverlayUpTo && p.mode != LabelMode::kWinding &&
         !p.screening && p.simple_rings;
}

// The small overlay's noding and snap rounding, if it takes the edge list and its re-check finds
// nothing the closure left (else the general ones run).
std::optional<Noded> node_small(const Pipeline& p) {
  if (!small_arrangement(p)) return std::nullopt;
  Noded n{find_contacts_small(p.edges), {}};
  if (!snap_round_small(p.edges, n.contacts, n.snapped)) return std::nullopt;
  discard(n.contacts.splits);
  discard(n.contacts.hot);
  return n;
}

// Noding with the operands' screen (when not validated yet) and the overlap budget; when the
// budget runs out, the stacks of collinear edges are merged (`merged`) and the merged edges
// noded again.
Noded node_operands(const Pipeline& p, std::optional<MergedEdges>& merged) {
  if (std::optional<Noded> small = node_small(p)) return std::move(*small);
  Noded n =
      node(p.edges, {p.simple_rings, p.screening ? &p.edges.channel : nullptr, overlap_budget(p)});
  if (!n.contacts.overlap_heavy) return n;
  merged = merge_collinear_overlaps(p.edges);
  n = node(merged->edges, {p.simple_rings});
  for (std::size_t s = 0; s < merged->edges.size(); ++s)
    if (merged->unchained[s]) n.snapped.touched[s] = true;
  return n;
}

// Screening after noding: whether to go on, and whether labeling checks single cover. Returns
// false when noding found an operand invalid (the caller validates in full).
bool screen_after_noding(Screening& screen, const Noded& noded, bool& check_cover) {
  if (noded.contacts.operand_invalid) {
    screen.suspect = true;
    return false;
  }
  if (noded.snapped.hot_pixels > 0) {  // moved: labeling's check would not be exact
    for (Operand which : {Operand::kSubject, Operand::kClip})
      if (screen.unchecked_multi_ring(which)) screen.validate_in_full(which);
  }
  check_cover =
      screen.unchecked_multi_ring(Operand::kSubject) || screen.unchecked_multi_ring(Operand::kClip);
  return true;
}

// Rings -> polygons: holed regions cut into hole-free pieces (hole_splitting.hpp), appended in
// canonical form with their label, and all of them in canonical order.
void collect_polygons(Assembled&& assembled, bool with_labels, PipelineResult& out) {
  out.clipped.polygons = std::move(assembled.rings);  // canonical rings
  out.labels.swap(assembled.labels);
  // Every region's pieces first, so the result's vector grows once.
  ScratchVector<Ring> pieces;
  ScratchVector<FaceLabel> piece_labels;
  for (RegionRings& region : assembled.holed) {
    split_holes(region.outers, region.holes, out.clipped.stats.holes_split, pieces);
    piece_labels.resize(pieces.size(), region.label);
  }
  out.clipped.polygons.reserve(out.clipped.polygons.size() + pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    out.clipped.polygons.push_back(canonical_ring(std::move(pieces[i])));
    out.labels.push_back(piece_labels[i]);
  }
  sort_canonical(out.clipped.polygons, with_labels ? &out.labels : nullptr);
  if (!with_labels) out.labels.clear();
}

}  // namespace

PipelineResult run(const Pipeline& p, std::vector<Box64>* moved_boxes, bool with_labels) {
  PipelineResult out;
  std::optional<MergedEdges> merged;
  Noded noded = node_operands(p, merged);  // edges -> contacts -> fragments
  const EdgeList& edges = merged ? merged->edges : p.edges;
  bool check_cover = false;
  if (p.screening && !screen_after_noding(*p.screening, noded, check_cover)) return out;
  if (p.check_stages) check_fragments(edges, noded.snapped.fragments, noded.snapped.touched);
  PlaneGraph graph;
  ScratchVector<SideState> labels;
  build_plane_graph(edges, noded.snapped, graph);  // consumes the fragments
  if (p.check_stages) check_plane_graph(graph);
  if (!label_sides(graph, p.mode, labels, check_cover)) {
    p.screening->suspect = true;
    return out;
  }
  if (p.check_stages) check_labels(graph, p.mode, labels);
  Assembled assembled =
      assemble(graph, labels, p.label_of, p.collinear_free_operands, p.corner_bridges);
  if (p.check_stages) check_assembled(assembled);
  collect_polygons(std::move(assembled), with_labels, out);
  out.clipped.stats.intersections = noded.contacts.intersections;
  out.clipped.stats.vertices_snapped = noded.snapped.hot_pixels;
  out.clipped.stats.zero_area_dropped = graph.cancelled_edges;
  if (moved_boxes)
    moved_boxes->assign(noded.snapped.moved_boxes.begin(), noded.snapped.moved_boxes.end());
  return out;
}

}  // namespace edgeland::detail
