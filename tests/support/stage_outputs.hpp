#pragma once
// The outputs of the pipeline's stages for given operands, each kept (clip/src/pipeline.cpp
// run() hands them on and drops them), made the way run() makes them. The one copy of the
// stage sequence in the tests: the stage checkers' tests corrupt these outputs, and the stage
// tests (stage_inputs.hpp) feed them to the stage under test.
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "assembly.hpp"
#include "collinear_merge.hpp"
#include "input_edges.hpp"
#include "labeling.hpp"
#include "noding.hpp"
#include "plane_graph.hpp"
#include "snap_rounding.hpp"

namespace edgeland::detail {

// Held by pointer: the graph points at edges.segments.
struct StageOutputs {
  EdgeList edges;
  std::vector<Fragment> fragments;
  std::vector<std::uint8_t> touched;
  std::size_t hot_pixels = 0;
  bool merged = false;  // stacks of collinear edges were merged (collinear_merge.hpp)
  PlaneGraph graph;
  LabelMode mode = LabelMode::kOwner;
  std::vector<SideState> left;
  Assembled assembled;
};

// Contacts then fragments of s.edges, as run() makes them (pipeline.cpp, node): snap rounding
// only when noding did not stop. Returns whether noding stopped at the overlap budget.
inline bool node_stage(StageOutputs& s, bool simple_rings, std::size_t overlap_budget,
                       Snapped& snapped) {
  SegmentSearch search(s.edges.segments, s.edges.next);
  Contacts contacts = find_contacts(s.edges.segments, s.edges.next, search,
                                    {simple_rings, nullptr, overlap_budget});
  if (!contacts.stopped()) snapped = snap_round(s.edges.segments, s.edges.next, contacts, search);
  return contacts.overlap_heavy;
}

// The edge list's snapped fragments, as run() makes them: with merged stacks when noding
// stops at the overlap budget, the merged edges' unchained segments then marked touched.
inline void snap_stage(StageOutputs& s, bool simple_rings, std::size_t overlap_budget) {
  Snapped snapped;
  if (node_stage(s, simple_rings, overlap_budget, snapped)) {
    MergedEdges merged = merge_collinear_overlaps(s.edges);
    s.edges = std::move(merged.edges);
    node_stage(s, simple_rings, std::numeric_limits<std::size_t>::max(), snapped);
    for (std::size_t k = 0; k < s.edges.size(); ++k)
      if (merged.unchained[k]) snapped.touched[k] = true;
    s.merged = true;
  }
  s.fragments.assign(snapped.fragments.begin(), snapped.fragments.end());
  s.touched = std::move(snapped.touched);
  s.hot_pixels = snapped.hot_pixels;
}

// Runs noding, snap rounding and the plane graph on s.edges.
inline void plane_graph_stages(
    StageOutputs& s, bool simple_rings,
    std::size_t overlap_budget = std::numeric_limits<std::size_t>::max()) {
  snap_stage(s, simple_rings, overlap_budget);
  build_plane_graph(s.edges, s.fragments, s.touched, s.graph);
}

// Runs the stages from noding to assembly on s.edges.
inline void later_stages(StageOutputs& s, LabelMode mode, const LabelOf& label_of,
                         bool simple_rings,
                         std::size_t overlap_budget = std::numeric_limits<std::size_t>::max()) {
  plane_graph_stages(s, simple_rings, overlap_budget);
  s.mode = mode;
  label_sides(s.graph, mode, s.left);
  s.assembled = assemble(s.graph, s.left, label_of, false);
}

// clip(op, subject, clip) on valid operands, as clip.cpp runs it (owner labels).
inline std::unique_ptr<StageOutputs> clip_stages(const PolygonSet& subject, const PolygonSet& clip,
                                                 ClipOp op) {
  auto s = std::make_unique<StageOutputs>();
  append_ring_edges(subject, kSubjectChannel, true, s->edges);
  append_ring_edges(clip, kClipChannel, true, s->edges);
  later_stages(*s, LabelMode::kOwner, LabelOf::operation(op), true);
  return s;
}

// normalize(rings, rule) as clip.cpp runs it (winding numbers); overlap_budget 0 merges every
// stack of collinear edges.
inline std::unique_ptr<StageOutputs> normalize_stages(
    const std::vector<Ring>& rings, FillRule rule,
    std::size_t overlap_budget = std::numeric_limits<std::size_t>::max()) {
  auto s = std::make_unique<StageOutputs>();
  append_ring_edges(rings, kSubjectChannel, false, s->edges);
  later_stages(*s, LabelMode::kWinding, LabelOf::fill(rule), false, overlap_budget);
  return s;
}

}  // namespace edgeland::detail
