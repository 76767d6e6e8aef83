#pragma once
// All intersections of a segment or of an infinite line with a ring's boundary (thesis 2.4).
//
// Half-open edges: edge i is taken as the points of v_i -> v_(i+1) WITHOUT its start v_i
// (thesis figure 9), so a query through a vertex reports that vertex once, on the edge that
// ends there. Collinear overlaps are reported as segments, one per edge: consecutive
// collinear edges give consecutive overlaps that share their common vertex (the thesis's
// "successive line intersections"). A point hit at the end vertex of edge i is dropped when
// the next edge of positive length reports an overlap starting there: the vertex is already
// covered by that overlap. Zero-length edges (repeated vertices) report nothing.
// For a simple ring every point where the query meets the boundary is therefore reported
// exactly once, as a point hit or inside one or two overlaps.
//
// Requires in-range points (point.hpp). Results are in increasing edge order.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/convexity.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland {

enum class BoundaryHitKind : std::uint8_t {
  kPoint,    // one common point: `point`
  kOverlap,  // a common part of positive length: overlap_from -> overlap_to
};

struct BoundaryHit {
  std::size_t edge = 0;  // edge i runs from vertex i to vertex (i + 1) mod n
  BoundaryHitKind kind = BoundaryHitKind::kPoint;
  // kPoint: the exact common point (an integer point unless the query crosses the edge's
  // interior; compare with cross-multiplication, it is not reduced).
  RationalPoint point;
  // kOverlap: the common part, ordered along the edge's direction (overlap_from is nearer
  // v_i). Both are integer points: each is an edge vertex or a query endpoint.
  Point64 overlap_from;
  Point64 overlap_to;
};

// The intersections of the closed segment `query` with the boundary. A degenerate query
// (a == b) is the single point a. With RingShape::kConvex the scan stops once the at most
// two points, or the one run of collinear overlaps, that a convex boundary can share with
// a line have been found (thesis 2.4.1); the result is the same as with kGeneral.
// O(n) (kConvex: O(n) worst case, about half the edges on average for a crossing query).
EDGELAND_EXPORT std::vector<BoundaryHit> boundary_intersections(
    const Segment& query, const Ring& ring, RingShape shape = RingShape::kGeneral);

// The intersections of the infinite line through line.a and line.b with the boundary.
// A degenerate line (a == b) is treated as the single point a. Same rules and complexity.
EDGELAND_EXPORT std::vector<BoundaryHit> line_boundary_intersections(
    const Segment& line, const Ring& ring, RingShape shape = RingShape::kGeneral);

}  // namespace edgeland
