#pragma once
// O(n^2) reference for validate(), used only by tests to cross-check the sweep.
//
// Written apart from the kernel on purpose: its own 128-bit orientation and segment tests,
// every pair of edges compared, and interiors compared through sub-edge midpoints located by
// an exact winding number (coordinates doubled so midpoints stay integers). It states the same
// rules as validate.hpp:
//   - fewer than 3 vertices: only that is reported for the ring;
//   - out-of-range coordinates and repeated consecutive vertices: reported per vertex; such a
//     ring gets no geometric check;
//   - spike at vertex i: a neighbour of vertex i lies on the other edge at vertex i;
//   - self-intersection: two non-adjacent edges of one ring share a point;
//   - not-counter-clockwise: a simple ring (no spike, no self-intersection) with area <= 0;
//   - overlapping interiors: between two rings that passed all of the above.
#include <cstddef>
#include <set>
#include <tuple>
#include <utility>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/validate.hpp"

namespace edgeland::testing {

struct BruteForceFindings {
  // (rule, polygon, vertex or edge index) for the per-ring rules; the index is the one
  // validate() puts in Violation::edge (kNone for too-few and orientation).
  std::set<std::tuple<Rule, std::size_t, std::size_t>> ring_rules;
  // (polygon, edge, other edge) for every pair of non-adjacent edges sharing a point.
  std::set<std::tuple<std::size_t, std::size_t, std::size_t>> self_intersections;
  // (i, j) with i < j for every pair of valid rings whose interiors overlap.
  std::set<std::pair<std::size_t, std::size_t>> overlaps;

  bool ok() const { return ring_rules.empty() && self_intersections.empty() && overlaps.empty(); }
  // (rule, polygon) pairs present, self-intersection and overlap included.
  std::set<std::pair<Rule, std::size_t>> rules_by_polygon() const;
};

BruteForceFindings validate_bruteforce(const PolygonSet& set);

// Whether the closed segments a0-a1 and b0-b1 share a point (independent of the kernel).
bool bruteforce_segments_meet(Point64 a0, Point64 a1, Point64 b0, Point64 b1);

// Whether two valid rings (simple, counter-clockwise) share interior points.
bool bruteforce_interiors_overlap(const Ring& a, const Ring& b);

}  // namespace edgeland::testing
