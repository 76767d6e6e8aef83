// The public operations: validate the input, run the pipeline of clip/README.md, check.
#include "edgeland/clip/clip.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "assembly.hpp"
#include "box_sweep.hpp"
#include "canonical.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "grown_box.hpp"
#include "hole_splitting.hpp"
#include "input_edges.hpp"
#include "labeling.hpp"
#include "operand_screen.hpp"
#include "pipeline.hpp"
#include "plane_graph.hpp"
#include "snap_rounding.hpp"
#include "valid_set_factory.hpp"

namespace edgeland {
namespace {

using detail::grown;
using detail::guarded;
using detail::Pipeline;
using detail::require_valid;
using detail::Screening;
using detail::SideState;

ClipResult run_clip(const Pipeline& p, std::vector<Box64>* moved_boxes = nullptr) {
  return detail::run(p, moved_boxes).clipped;
}

// clip() restricted to the subject polygons that can interact with the clip operand.
// A subject polygon is left out when its box stays clear of the clip operand's box and of every
// segment snap rounding moved (one unit of margin: a snapped segment stays within half a unit of
// where it was). Left-out polygons are unaffected by the operation: kept as they are, or dropped
// by an intersection. If rounding moved a segment near a left-out polygon, that polygon is
// brought in and the operation re-run; the included set only grows, so this terminates.
// collinear_free: no ring of either operand has collinear consecutive vertices.
// subject_canonical: the subject is in canonical form (an earlier result), so left-out polygons
// are copied as they are and merged into the sorted result.
// check_stages: run the stage checkers (checked mode).
ClipResult clip_near(ClipOp op, const PolygonSet& subject, const PolygonSet& clip_set,
                     bool subject_canonical, bool collinear_free, bool check_stages,
                     Screening* screening = nullptr) {
  std::vector<Box64> boxes(subject.size());
  for (std::size_t i = 0; i < subject.size(); ++i) boxes[i] = *bounding_box(subject[i]);
  std::vector<bool> included(subject.size(), false);
  if (const auto cb = bounding_box(clip_set)) {
    const Box64 reach = grown(*cb, 1);
    for (std::size_t i = 0; i < subject.size(); ++i) included[i] = boxes[i].overlaps(reach);
  }
  // Left-out subject polygons never reach the pipeline, so its checks cannot vouch for them.
  if (screening && std::find(included.begin(), included.end(), false) != included.end())
    screening->validate_in_full(Operand::kSubject);
  for (;;) {
    Pipeline p;
    p.check_stages = check_stages;
    p.screening = screening;
    std::vector<std::uint32_t> near;
    for (std::uint32_t i = 0; i < subject.size(); ++i)
      if (included[i]) near.push_back(i);
    detail::append_ring_edges(subject, detail::kSubjectChannel, true, p.edges, &near);
    detail::append_ring_edges(clip_set, detail::kClipChannel, true, p.edges);
    p.mode = detail::LabelMode::kOwner;
    p.label_of = detail::LabelOf::operation(op);
    p.collinear_free_operands = collinear_free;
    std::vector<Box64> moved;
    ClipResult r = run_clip(p, &moved);
    if (screening && screening->suspect) return r;

    std::vector<Box64> left_out;
    std::vector<std::size_t> left_out_index;
    for (std::size_t i = 0; i < subject.size(); ++i)
      if (!included[i]) {
        left_out.push_back(grown(boxes[i], 1));
        left_out_index.push_back(i);
      }
    bool grew = false;
    detail::for_each_overlapping_pair(left_out, moved, [&](std::uint32_t k, std::uint32_t) {
      if (!included[left_out_index[k]]) included[left_out_index[k]] = grew = true;
    });
    if (grew) continue;
    if (op == ClipOp::kIntersection) return r;
    const auto computed = static_cast<std::ptrdiff_t>(r.polygons.size());
    for (std::size_t i : left_out_index)
      r.polygons.push_back(subject_canonical ? subject[i] : detail::canonical_ring(subject[i]));
    // The computed part is sorted; so are the left-out polygons of a canonical subject, and
    // otherwise they are sorted alone (usually a few) before the two parts are merged.
    if (!subject_canonical) std::sort(r.polygons.begin() + computed, r.polygons.end());
    std::inplace_merge(r.polygons.begin(), r.polygons.begin() + computed, r.polygons.end());
    return r;
  }
}

// The box is the clip operand: a corner beyond the bound, then min > max, is refused.
void require_valid_box(const Box64& box) {
  for (const Point64 corner : {box.min, box.max})
    if (!in_range(corner)) throw CoordinateOutOfRange(Operand::kClip, 0, 0, kNone, corner);
  if (box.min.x > box.max.x || box.min.y > box.max.y) throw InvalidBox(Operand::kClip, box);
}

// subject OP clip for operands known to be valid; *_canonical: that operand is in canonical
// form (an earlier result).
ClipResult clip_of_valid(ClipOp op, const PolygonSet& subject, const PolygonSet& clip_set,
                         const ClipOptions& options, bool subject_canonical = false,
                         bool collinear_free = false) {
  return guarded(
      [&] {
        return clip_near(op, subject, clip_set, subject_canonical, collinear_free, options.checked);
      },
      options, op_name(op), [&] { return to_wkt(subject); }, [&] { return to_wkt(clip_set); });
}

// collinear_free: no ring of the set has collinear consecutive vertices (the box has none).
ClipResult box_of_valid(const PolygonSet& set, const Box64& box, const ClipOptions& options,
                        bool collinear_free) {
  if (box.min.x == box.max.x || box.min.y == box.max.y) return {};
  // Members that cannot reach the box take no part; the rest go through the full pipeline,
  // so the result stays closed under repetition exactly like clip().
  std::vector<std::uint32_t> near;
  for (std::uint32_t i = 0; i < set.size(); ++i)
    if (bounding_box(set[i])->overlaps(box)) near.push_back(i);
  const PolygonSet cell{{box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}}};
  // gcov ascribes the unwinding of `p` below, run only when the pipeline throws (an internal
  // error), to the `[&] {` line: not reached by tests.
  return guarded(
      [&] {
        Pipeline p;
        p.check_stages = options.checked;
        detail::append_ring_edges(set, detail::kSubjectChannel, true, p.edges, &near);
        detail::append_ring_edges(cell, detail::kClipChannel, true, p.edges);
        p.mode = detail::LabelMode::kOwner;
        p.label_of = detail::LabelOf::operation(ClipOp::kIntersection);
        p.collinear_free_operands = collinear_free;
        return run_clip(p);
      },
      options, "clip_to_box", [&] { return to_wkt(set); }, [&] { return to_wkt(cell); });
}

// Every ring routed through the hot pixels of all of them snapped together (snap_rounding.hpp),
// as closed integer polylines in their own direction: the routes meet one another and
// themselves only at shared vertices or along shared stretches, never crossing.
std::vector<Ring> snapped_rings(const std::vector<Ring>& rings, ClipStats& stats) {
  detail::EdgeList edges;
  detail::append_ring_edges(rings, detail::kSubjectChannel, true, edges);
  const detail::Snapped snapped =
      detail::node_and_snap_round(edges.segments, edges.next, false, &stats.intersections);
  const auto& fragments = snapped.fragments;
  stats.vertices_snapped = snapped.hot_pixels;
  // Listed fragments come in segment order, each segment's from its start to its end; a
  // segment with none listed is its own fragment.
  std::vector<Ring> out(rings.size());
  std::size_t f = 0;
  for (std::uint32_t s = 0; s < edges.size(); ++s) {
    Ring& route = out[static_cast<std::size_t>(edges.polygon[s])];
    if (f == fragments.size() || fragments[f].parent != s) {
      route.push_back(edges.segments[s].a);
      continue;
    }
    for (; f < fragments.size() && fragments[f].parent == s; ++f)
      route.push_back(fragments[f].seg.a);
  }
  return out;
}

}  // namespace

const char* op_name(ClipOp op) noexcept {
  switch (op) {
    case ClipOp::kUnion:
      return "union";
    case ClipOp::kIntersection:
      return "intersection";
    case ClipOp::kDifference:
      return "difference";
    case ClipOp::kXor:
      return "xor";
  }
  return "?";  // Not reached by tests: the switch covers every ClipOp.
}

const char* fill_rule_name(FillRule rule) noexcept {
  switch (rule) {
    case FillRule::kEvenOdd:
      return "evenodd";
    case FillRule::kNonZero:
      return "nonzero";
    case FillRule::kPositive:
      return "positive";
    case FillRule::kNegative:
      return "negative";
  }
  return "?";  // Not reached by tests: the switch covers every FillRule.
}

InternalError::InternalError(const std::string& what, std::string subject, std::string clip)
    : Error("edgeland internal error (please report with the inputs): " + what),
      subject_wkt(std::move(subject)),
      clip_wkt(std::move(clip)) {}

ClipResult clip(ClipOp op, const PolygonSet& subject, const PolygonSet& clip_set,
                const ClipOptions& options) {
  auto validate_both = [&] {
    require_valid(subject, Operand::kSubject);
    require_valid(clip_set, Operand::kClip);
  };
  // Validated while clipped (Screening); anything the screen or the pipeline doubts is
  // validated in full, so errors are exactly validate()'s, subject first.
  if (!detail::rings_pass_screen(subject) || !detail::rings_pass_screen(clip_set)) {
    validate_both();
    // Not reached by tests: every valid set passes the screen (the least vertex of a valid
    // ring is a strict left turn), so validate_both() has thrown; kept should the screen
    // ever be stricter than validate().
    return clip_of_valid(op, subject, clip_set, options);
  }
  Screening screen{{&subject, &clip_set}};
  ClipResult r = guarded(
      [&] { return clip_near(op, subject, clip_set, false, false, options.checked, &screen); },
      options, op_name(op), [&] { return to_wkt(subject); }, [&] { return to_wkt(clip_set); },
      validate_both);
  if (!screen.suspect) return r;
  validate_both();
  // Not reached by tests: the pipeline finds only invalid operands suspect, and then
  // validate_both() has thrown; kept for a false alarm of the screen.
  return clip_of_valid(op, subject, clip_set, options);
}

ValidSet::ValidSet(PolygonSet set, Operand which) : set_(std::move(set)) {
  require_valid(set_, which);
  collinear_free_ = detail::collinear_free(set_);
}

ValidClipResult clip(ClipOp op, const ValidSet& subject, const ValidSet& clip_set,
                     const ClipOptions& options) {
  return ValidSetFactory::from(clip_of_valid(
      op, subject.polygons(), clip_set.polygons(), options, ValidSetFactory::canonical(subject),
      ValidSetFactory::collinear_free(subject) && ValidSetFactory::collinear_free(clip_set)));
}

ValidClipResult clip_to_box(const ValidSet& set, const Box64& box, const ClipOptions& options) {
  require_valid_box(box);
  return ValidSetFactory::from(
      box_of_valid(set.polygons(), box, options, ValidSetFactory::collinear_free(set)));
}

ClipResult normalize(const std::vector<Ring>& rings, FillRule rule, const ClipOptions& options) {
  for (std::size_t r = 0; r < rings.size(); ++r)
    for (std::size_t i = 0; i < rings[r].size(); ++i)
      if (!in_range(rings[r][i])) throw CoordinateOutOfRange(Operand::kRings, r, 0, i, rings[r][i]);
  // gcov ascribes the unwinding of `p` below, run only when the pipeline throws, to the `[&] {`
  // line, and the WKT lambda below is called only then (an internal error): not reached by
  // tests.
  return guarded(
      [&] {
        Pipeline p;
        p.check_stages = options.checked;
        detail::append_ring_edges(rings, detail::kSubjectChannel, false, p.edges);
        p.simple_rings = false;
        p.mode = detail::LabelMode::kWinding;
        p.label_of = detail::LabelOf::fill(rule);
        return run_clip(p);
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
  // Each ring stands for the region it winds around (non-zero rule). A strictly simple ring
  // is that region's boundary once it turns the right way: exteriors counter-clockwise, holes
  // clockwise; then the sum of +1 over exteriors and -1 over holes is filled where positive.
  // A ring that is not simple (a bow tie, a spike, a figure eight: invalid OGC, common in
  // foreign data) is replaced by the boundaries of its own non-zero region, so every lobe of a
  // self-crossing exterior counts, whichever way it turns (orienting it by its total signed
  // area would keep only the lobes turning with the larger ones; GEOS and PostGIS MakeValid
  // keep them all too).
  std::vector<Ring> rings;
  std::vector<bool> exterior, simple;
  for (const auto& polygon : polygons)
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      Ring ring = polygon[k];
      for (std::size_t i = 0; i < ring.size(); ++i)
        if (!in_range(ring[i])) {
          const auto index = static_cast<std::size_t>(&polygon - polygons.data());
          throw CoordinateOutOfRange(Operand::kRings, index, k, i, ring[i]);
        }
      // Repeated points (a closing point copied from WKT or GeoJSON among them) change no
      // winding number; without them a valid ring passes the simplicity test below.
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
      if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
      if (twice_signed_area(ring) < 0) std::reverse(ring.begin(), ring.end());
      simple.push_back(validate(ring, 1).ok());  // strictly simple (and now CCW)
      exterior.push_back(k == 0);
      if (k > 0) std::reverse(ring.begin(), ring.end());
      rings.push_back(std::move(ring));
    }
  // One strictly simple ring without holes is a valid set already: its canonical form is what
  // normalize would return, at the cost of the check above (a 4 * 10^5-vertex polygon minus the
  // empty set spent 80% of its time re-noding it).
  if (rings.size() == 1 && simple[0]) {
    ClipResult out;
    out.polygons.push_back(detail::canonical_ring(std::move(rings[0])));
    return out;
  }
  if (std::find(simple.begin(), simple.end(), false) == simple.end())
    return normalize(rings, FillRule::kPositive, options);  // valid OGC input: one pass
  // One rounding for everything: all rings are snapped together first, after which filling
  // a ring alone, or all of them, meets only integer contacts and rounds nothing more.
  // (Snapping each odd ring alone and then all together would round twice; a vertex could
  // then lie farther than a unit from the exact boundary, and a property test found one.)
  ClipStats snapped_stats;
  const std::vector<Ring> snapped = snapped_rings(rings, snapped_stats);
  std::vector<Ring> filled;
  for (std::size_t r = 0; r < snapped.size(); ++r) {
    if (simple[r]) {
      filled.push_back(snapped[r]);
      continue;
    }
    for (Polygon& piece : normalize({snapped[r]}, FillRule::kNonZero, options).polygons) {
      if (!exterior[r]) std::reverse(piece.begin(), piece.end());
      filled.push_back(std::move(piece));
    }
  }
  ClipResult out = normalize(filled, FillRule::kPositive, options);
  out.stats.intersections = snapped_stats.intersections;
  out.stats.vertices_snapped = snapped_stats.vertices_snapped;
  return out;
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

ClipResult clip_to_box(const PolygonSet& set, const Box64& box, const ClipOptions& options) {
  require_valid_box(box);
  require_valid(set, Operand::kSubject);
  return box_of_valid(set, box, options, false);
}

}  // namespace edgeland
