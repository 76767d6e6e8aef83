#pragma once
// The one way an operation sets up the pipeline (pipeline.hpp): which rings go in as which
// operand, how faces are labeled, and what the operands are known to satisfy. clip(),
// clip_to_box(), normalize() and the labeled overlays (relabel.hpp) each describe their
// pipeline with it and run it:
//
//   PipelineBuilder(LabelMode::kOwner, LabelOf::operation(op), options.checked)
//       .subject(subject, &near)
//       .clip(clip_set)
//       .collinear_free(true)
//       .run();
//
// Edges are appended in the order of the calls, so an operation's edge list (and with it every
// tie broken by edge order) is fixed by its description.
#include <cstdint>
#include <vector>

#include "pipeline.hpp"

namespace edgeland::detail {

class PipelineBuilder {
 public:
  // Faces labeled by `mode`, their result label looked up by `label_of`; with check_stages
  // every stage's result is checked (checked mode).
  PipelineBuilder(LabelMode mode, LabelOf label_of, bool check_stages) {
    p_.mode = mode;
    p_.label_of = label_of;
    p_.check_stages = check_stages;
  }

  // The subject (channel 0) or clip (channel 1) operand: the polygons listed in `members` (all
  // when null), each edge tagged with its polygon's index in `polygons`.
  PipelineBuilder& subject(const std::vector<Ring>& polygons,
                           const std::vector<std::uint32_t>* members = nullptr) {
    append_ring_edges(polygons, kSubjectChannel, true, p_.edges, members);
    return *this;
  }
  PipelineBuilder& clip(const std::vector<Ring>& polygons,
                        const std::vector<std::uint32_t>* members = nullptr) {
    append_ring_edges(polygons, kClipChannel, true, p_.edges, members);
    return *this;
  }
  // A box as a clip operand ring (counter-clockwise from min), its edges tagged `tag`: no ring
  // built for it, as a labeled overlay's window is added on every call.
  PipelineBuilder& clip_box(const Box64& box, std::int32_t tag = 0) {
    append_box_edges(box, kClipChannel, tag, p_.edges);
    return *this;
  }
  // The edges appended since `from` count `weight` times each (EdgeList::weight), the edges
  // before them once: a batch overlay's shapes, each counted with its own power of four
  // (relabel_pipeline.hpp).
  PipelineBuilder& weighted_from(std::size_t from, std::int32_t weight) {
    if (p_.edges.weight.empty()) p_.edges.weight.assign(from, 1);
    p_.edges.weight.resize(p_.edges.size(), weight);
    return *this;
  }
  std::size_t edge_count() const { return p_.edges.size(); }
  // normalize()'s rings: one untagged operand (winding numbers), rings that may cross
  // themselves.
  PipelineBuilder& winding_rings(const std::vector<Ring>& rings) {
    append_ring_edges(rings, kSubjectChannel, false, p_.edges);
    p_.simple_rings = false;
    return *this;
  }

  // No operand ring has collinear consecutive vertices (Pipeline::collinear_free_operands).
  PipelineBuilder& collinear_free(bool operands_collinear_free) {
    p_.collinear_free_operands = operands_collinear_free;
    return *this;
  }
  // Holes bridged only at their region's corners (Pipeline::corner_bridges).
  PipelineBuilder& corner_bridges() {
    p_.corner_bridges = true;
    return *this;
  }
  // Few segments take the small overlay's noding and snap rounding (Pipeline::small_overlay).
  PipelineBuilder& small_overlay(bool on) {
    p_.small_overlay = on;
    return *this;
  }
  // Operands not validated yet, checked while clipped (Screening); null: validated.
  PipelineBuilder& screened_by(Screening* screening) {
    p_.screening = screening;
    return *this;
  }

  // run() of pipeline.hpp on the described pipeline.
  PipelineResult run(std::vector<Box64>* moved_boxes = nullptr, bool with_labels = false) const {
    return detail::run(p_, moved_boxes, with_labels);
  }
  // The polygons and stats alone.
  ClipResult clipped(std::vector<Box64>* moved_boxes = nullptr) const {
    return run(moved_boxes).clipped;
  }

 private:
  Pipeline p_;
};

}  // namespace edgeland::detail
