// The per-ring rules that need no sweep: vertex count, coordinate range, repeated vertices,
// spikes and orientation (validate.hpp).
#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "validate_checks.hpp"

namespace edgeland::detail {
namespace {

Violation ring_violation(Rule rule, std::size_t polygon, std::size_t edge, Point64 where) {
  Violation v;
  v.rule = rule;
  v.polygon = polygon;
  v.edge = edge;
  v.where = where;
  return v;
}

// Twice the signed area as a fan from vertex 0: each term is one orientation determinant
// (< 2^66 for in-range points), so the sum fits Int128 for any ring shorter than 2^61.
Int128 twice_area_fan(const Ring& ring) {
  using W = arith::Checked<Int128>;
  W sum = 0;
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
    sum = sum + W(orient_det(ring[0], ring[i], ring[i + 1]));
  }
  return sum.v;
}

}  // namespace

bool check_ring_structure(const Ring& ring, std::size_t polygon, ViolationSink& sink) {
  const std::size_t n = ring.size();
  if (n < 3) {
    sink.add(ring_violation(Rule::kTooFewVertices, polygon, kNone, n == 0 ? Point64{} : ring[0]));
    return false;
  }
  bool ok = true;
  for (std::size_t i = 0; i < n; ++i) {
    if (!in_range(ring[i])) {
      // `edge` names the vertex here: edge i starts at vertex i.
      sink.add(ring_violation(Rule::kCoordinateOutOfRange, polygon, i, ring[i]));
      ok = false;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (ring[i] == ring[(i + 1) % n]) {
      sink.add(ring_violation(Rule::kRepeatedVertex, polygon, i, ring[i]));
      ok = false;
    }
  }
  return ok;
}

bool check_spikes(const Ring& ring, std::size_t polygon, ViolationSink& sink) {
  const std::size_t n = ring.size();
  bool ok = true;
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 prev = ring[(i + n - 1) % n], at = ring[i], next = ring[(i + 1) % n];
    // Both neighbours on one ray from the vertex: the two edges overlap along it.
    if (orientation(prev, at, next) == Orientation::kCollinear && dot_sign(at, prev, next) > 0) {
      Violation v = ring_violation(Rule::kSpike, polygon, (i + n - 1) % n, at);
      v.other_edge = i;
      sink.add(v);
      ok = false;
    }
  }
  return ok;
}

bool check_orientation(const Ring& ring, std::size_t polygon, ViolationSink& sink) {
  if (twice_area_fan(ring) > 0) return true;
  sink.add(ring_violation(Rule::kNotCounterClockwise, polygon, kNone,
                          *std::min_element(ring.begin(), ring.end())));
  return false;
}

}  // namespace edgeland::detail
