// validate(): the per-ring rules, then the sweep for disjoint interiors (validate.hpp).
#include "edgeland/kernel/validate.hpp"

#include <span>

#include "validate_checks.hpp"
#include "validate_report_sweep.hpp"

namespace edgeland {
namespace {

// Checks one ring; returns whether it is valid on its own (and so may join the set check).
// `quick` first tries the one-sweep acceptance, which settles a valid ring with no report.
bool validate_ring(const Ring& ring, std::size_t polygon, detail::ViolationSink& sink,
                   std::vector<detail::SweepEdge>& scratch, bool quick) {
  if (quick && detail::accepted_by_one_sweep(std::span<const Ring>(&ring, 1))) return true;
  if (!detail::check_ring_structure(ring, polygon, sink)) return false;
  bool simple = detail::check_spikes(ring, polygon, sink);
  scratch.clear();
  detail::append_ring_edges(ring, polygon, scratch);
  detail::sort_for_sweep(scratch);
  if (auto v = detail::find_self_intersection(scratch, ring.size())) {
    sink.add(*v);
    simple = false;
  }
  // The sign of the area says nothing about a ring that is not simple.
  return simple && detail::check_orientation(ring, polygon, sink);
}

ValidationReport validate_polygons(std::span<const Polygon> polygons, std::size_t max_violations) {
  // Valid inputs are the common case (the clipper checks every operand): one sweep proves
  // them valid. Anything else takes the reporting checks below, which alone decide the report.
  if (detail::accepted_by_one_sweep(polygons)) return {};
  detail::ViolationSink sink(max_violations);
  std::vector<detail::SweepEdge> edges;
  std::vector<std::size_t> valid_rings;
  // A lone polygon just failed the one-sweep acceptance: no need to try it again.
  const bool quick = polygons.size() > 1;
  for (std::size_t i = 0; i < polygons.size() && !sink.full(); ++i) {
    if (validate_ring(polygons[i], i, sink, edges, quick)) valid_rings.push_back(i);
  }
  if (valid_rings.size() >= 2 && !sink.full()) {
    edges.clear();
    for (const std::size_t i : valid_rings) detail::append_ring_edges(polygons[i], i, edges);
    detail::sort_for_sweep(edges);
    // One sweep finds one overlapping pair; drop the later member and look again, so each
    // further sweep can only report a new pair. Members found disjoint by the one-sweep
    // acceptance have no pair left to report (when every ring is valid, the acceptance of
    // them all has just failed: no need to try it again). It is tried once only: after a
    // pair is found, more pairs are the likely case (a file of copies), where trying it before
    // every reporting sweep doubled the work.
    if (valid_rings.size() < polygons.size() &&
        detail::accepted_by_one_sweep(polygons, valid_rings)) {
      return ValidationReport{sink.take()};
    }
    while (!sink.full()) {
      const auto v = detail::find_overlap(edges);
      if (!v) break;
      sink.add(*v);
      const std::size_t dropped = v->other_polygon != kNone ? v->other_polygon : v->polygon;
      std::erase_if(edges, [&](const detail::SweepEdge& e) { return e.polygon == dropped; });
      std::erase(valid_rings, dropped);
    }
  }
  return ValidationReport{sink.take()};
}

}  // namespace

ValidationReport validate(const Polygon& polygon, std::size_t max_violations) {
  return validate_polygons(std::span<const Polygon>(&polygon, 1), max_violations);
}

ValidationReport validate(const PolygonSet& set, std::size_t max_violations) {
  return validate_polygons(std::span<const Polygon>(set), max_violations);
}

}  // namespace edgeland
