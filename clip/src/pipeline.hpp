#pragma once
// The pipeline of clip/README.md as one call: the tagged edges of the operands in, the
// canonical result polygons out. clip(), clip_to_box(), normalize() and the labeled overlays
// (relabel.hpp) each describe theirs with a PipelineBuilder (pipeline_builder.hpp) and run it.
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "edgeland/clip/errors.hpp"
#include "edgeland/clip/types.hpp"
#include "edgeland/kernel/canonical_form.hpp"
#include "edgeland/kernel/validate.hpp"
#include "face_label.hpp"
#include "input_edges.hpp"
#include "labeling.hpp"

namespace edgeland::detail {

// Throws InvalidInput naming `which` with validate()'s first violation.
void require_valid(const PolygonSet& set, Operand which);

// The validating clip() checks its operands while it clips them (clip/README.md, "Validating
// while clipping"): the O(n) rules first (operand_screen.hpp), then noding stops at any ring
// meeting itself or members of one operand crossing or overlapping alike (noding.hpp), and
// labeling at any face covered twice by one operand. Labeling's check is
// exact only when snap rounding moved nothing; when it moved something, an operand of several
// rings is validated in full instead (one ring needs no coverage check). Should anything look
// wrong, the pipeline stops (`suspect`) and the caller validates both operands in full, which
// names the violation, or finds none and clips them as valid.
struct Screening {
  const PolygonSet* operand[2];  // by channel (input_edges.hpp): the subject, then the clip
  bool validated[2] = {false, false};
  bool suspect = false;

  void validate_in_full(Operand which) {
    const std::uint8_t c = channel_of(which);
    if (validated[c]) return;
    require_valid(*operand[c], which);
    validated[c] = true;
  }
  bool unchecked_multi_ring(Operand which) const {
    const std::uint8_t c = channel_of(which);
    return !validated[c] && operand[c]->size() > 1;
  }
};

struct Pipeline {
  EdgeList edges;  // in scratch storage (edgeland/kernel/scratch.hpp), as are all stage arrays
  LabelMode mode;
  LabelOf label_of = LabelOf::operation(ClipOp::kUnion);
  // No operand ring has collinear consecutive vertices: only graph vertices can be collinear.
  bool collinear_free_operands = false;
  bool simple_rings = true;  // validated operands; normalize's rings may cross themselves
  // Holes are bridged only at corners of their region and at points where two of its rings
  // touch (assembly.hpp), so the pieces depend on the region alone (relabel.hpp).
  bool corner_bridges = false;
  // Few segments may take the small overlay's noding and snap rounding (small_overlay.hpp): the
  // landscape's cell overlays. The result is the same; relabel() keeps the general ones, so that
  // the two can be compared.
  bool small_overlay = false;
  Screening* screening = nullptr;  // operands not validated yet (noding then tests all pairs)
  // Checked mode: every stage's result is checked (stage_checks.hpp) before the next stage
  // reads it.
  bool check_stages = false;
  // Winding labelings: how many pairs of edges may overlap along a stretch before stacks of
  // collinear edges are merged (collinear_merge.hpp); unset: 4 per edge plus 4096. (Tests set
  // 0 to merge every stack.)
  std::optional<std::size_t> overlap_budget;
};

// The result of run(): canonical polygons in canonical order, and when asked for, the face
// label each came from (labels[i] for polygons[i]).
struct PipelineResult {
  ClipResult clipped;
  ScratchVector<FaceLabel> labels;
};

// Runs the stages on p.edges. moved_boxes (optional): the boxes of every segment snap rounding
// moved. with_labels: fill PipelineResult::labels. When p.screening finds a suspect operand the
// result is empty and p.screening->suspect is set.
PipelineResult run(const Pipeline& p, std::vector<Box64>* moved_boxes = nullptr,
                   bool with_labels = false);

// Runs the pipeline; any failure of an internal invariant becomes an InternalError with the
// inputs, and in checked mode so does an output that fails validation or is not in canonical
// form. Operands not validated yet are validated before an InternalError is thrown
// (`validate_inputs`): a pipeline fed an invalid operand may fail anywhere, and that is the
// caller's InvalidInput, not a bug.
inline const PolygonSet& result_polygons(const ClipResult& r) { return r.polygons; }
inline const PolygonSet& result_polygons(const PipelineResult& r) { return r.clipped.polygons; }

template <class F>
auto guarded(F&& body, const ClipOptions& options, const std::string& what,
             const std::function<std::string()>& subject_wkt,
             const std::function<std::string()>& clip_wkt,
             const std::function<void()>& validate_inputs = {}) {
  decltype(body()) r;
  try {
    r = body();
  } catch (const std::logic_error& e) {
    // Not reached by tests: no test input breaks an internal invariant of the pipeline (the
    // fuzzers look for one).
    if (validate_inputs) validate_inputs();
    throw InternalError(what + ": " + e.what(), subject_wkt(), clip_wkt());
  }
  if (options.checked) {
    const ValidationReport report = validate(result_polygons(r), 1);
    if (!report.ok())  // Not reached by tests: no test input yields an invalid output.
      throw InternalError(what + ": invalid output: " + report.violations.front().describe(),
                          subject_wkt(), clip_wkt());
    if (const auto order =
            canonical_violation(result_polygons(r)))  // Not reached by tests, as above.
      throw InternalError(what + ": output not in canonical form: " + order->describe(),
                          subject_wkt(), clip_wkt());
  }
  return r;
}

}  // namespace edgeland::detail
