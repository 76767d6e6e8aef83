#pragma once
// Point-in-polygon (thesis 2.5): inside / outside / on the boundary, exactly.
//
// The general test casts the horizontal ray from p toward +x and counts signed crossings
// (the winding number). The special cases of thesis 2.5.1 (figures 13 and 15) are decided
// by one rule instead of by inspecting neighbours: a vertex exactly on the ray's line counts
// as lying BELOW it, so every edge is half-open in y (it may cross the ray only where
// min(y) <= p.y < max(y)). Then
//  - a ray through a vertex whose two neighbours are on the same side (fig. 15, a0 and a1)
//    crosses either both edges or neither, which cancels in the signed count;
//  - a ray through a vertex whose neighbours are on opposite sides (fig. 15, b) crosses
//    exactly one of the two edges;
//  - edges lying along the ray never count, and the edges before and after a collinear run
//    count once exactly when they lie on opposite sides (fig. 15, c).
// Points on an edge are recognised first (fig. 13, r), exactly, and reported as such.
#include <cstdint>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

enum class PointLocation : std::uint8_t { kOutside, kInside, kOnBoundary };

// How many times the ring winds counter-clockwise around p (negative for clockwise turns).
// Precondition: p is not on the boundary (there the count is not meaningful; the value
// returned is still deterministic). Any ring: orientation, self-intersections and repeated
// vertices are all allowed. O(n).
EDGELAND_EXPORT int winding_number(Point64 p, const Ring& ring) noexcept;

// kOnBoundary if p lies on a (closed) edge; otherwise kInside iff winding_number != 0 (the
// nonzero rule). For a simple ring that is the usual inside, in either orientation; a point
// that a self-intersecting ring winds around twice (the core of a pentagram) is inside too.
// Fewer than 3 vertices: only the boundary (a point or a segment) exists. O(n).
EDGELAND_EXPORT PointLocation locate(Point64 p, const Ring& ring) noexcept;

// The half-open rule (the pixel convention of round_to_grid, and the landscape's material_at):
// whether the points p + eps (1, eps) are inside the ring for every small enough eps > 0.
// Every point of the plane is then inside exactly one face of a partition by rings: a point on
// an edge or a vertex belongs to the face to its east (north-east for a horizontal edge).
// Any ring; nonzero winding rule. O(n).
EDGELAND_EXPORT bool inside_half_open(Point64 p, const Ring& ring) noexcept;

// The convex fast path of thesis 2.5.2 in O(log n): binary search for the fan triangle
// (v_0, v_k, v_(k+1)) whose wedge at v_0 holds p, then one orientation test.
// Precondition: is_convex(ring) and the ring is counter-clockwise; collinear vertices are
// allowed (also at v_0). Violating it gives unspecified (but memory-safe) answers.
EDGELAND_EXPORT PointLocation locate_convex(Point64 p, const Ring& convex_ccw_ring) noexcept;

// Location with respect to a polygon set (polygon.hpp: interiors pairwise disjoint):
// kOnBoundary if p is on the boundary of some member (also where two members touch, which
// may lie inside the union), kInside if p is inside a member, else kOutside.
// A member whose bounding box misses p is skipped after comparisons only; its box costs
// O(size) to compute, so callers that query often pass precomputed boxes to the second
// overload (boxes[i] = bounding_box(set[i]), empty members may hold any box).
// O(total vertices) worst case; members with p outside their box cost no exact arithmetic.
EDGELAND_EXPORT PointLocation locate(Point64 p, const PolygonSet& set) noexcept;
EDGELAND_EXPORT PointLocation locate(Point64 p, const PolygonSet& set,
                                     const std::vector<Box64>& boxes) noexcept;

}  // namespace edgeland
