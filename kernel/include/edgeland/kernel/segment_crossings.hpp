#pragma once
// Where a segment enters and leaves the interior of a ring (thesis 2.4 for the landscape's ray
// and profile queries), with every degenerate contact decided by one rule.
//
// THE PERTURBATION. The segment a -> b is taken as moved by the infinitesimal vector
// delta = eps * (1, eps): the vector by which the half-open rule of pixels and of
// inside_half_open (point_in_polygon.hpp) looks at a point. The moved segment passes through no
// vertex and runs along no edge, so it meets the boundary only in proper crossings; a vertex
// on the line through a and b counts as lying on the side the moved line leaves it on: the
// side of sign(dy), or of -sign(dx) for a horizontal segment (a vertex on a horizontal line is
// below the line moved up). Each crossing is reported at its limit, the parameter t of the
// exact point where the unmoved line crosses the edge, or the vertex it passes (t of that
// vertex). Two crossings of one ring share a limit only where the moved line cuts off the tip
// of a vertex: one enters, one leaves, and the interval between has zero length.
//
// Consequence: inside_half_open(a + t (b - a)) holds between crossings exactly when the
// segment is inside there (for t not at a crossing), so a segment along a boundary between two
// regions is in the region the point query picks, and along a seam of two pieces of one
// region it is in one of them, never in neither.
//
// Magnitudes: t = num / den where num and den are orientation determinants or dot products of
// in-range points or their difference (below 2^66): compare them with edgeland::compare.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/fraction.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland {

struct SegmentCrossing {
  Fraction t;              // the limit parameter: the point a + t (b - a), den > 0
  std::uint32_t edge = 0;  // the edge crossed (edge i runs from vertex i to vertex i + 1)
  bool entering = false;   // from outside into the interior (a front face, thesis 2.4.2)
  bool at_vertex = false;  // the limit point is a vertex of that edge: `vertex`
  std::uint32_t vertex = 0;
};

// Which crossings to list: all, or only the entering ones (back faces culled, thesis 2.4.2).
enum class CrossingCulling : std::uint8_t { kNone, kBackFaces };

struct RingCrossings {
  // Whether the moved segment is inside just before its start (t -> 0 from below): counted
  // from the crossings with t < 0 (computed only when asked for).
  bool inside_before = false;
  // The crossings with 0 <= t <= 1, by increasing t (ties by edge index).
  std::vector<SegmentCrossing> crossings;
};

// The crossings of segment s (s.a != s.b) with a simple counter-clockwise ring (at least 3
// vertices, in range). with_inside_before: also count the crossings before t = 0. O(n + c log c)
// for c crossings listed; an edge with both ends strictly on one side costs two orientation
// tests, the second shared with the next edge.
EDGELAND_EXPORT RingCrossings segment_crossings(const Segment& s, const Ring& ring,
                                                CrossingCulling culling = CrossingCulling::kNone,
                                                bool with_inside_before = true);

// The exact point of a crossing returned for (s, ring): the vertex, or the intersection of the
// line through s with the edge. O(1).
EDGELAND_EXPORT RationalPoint crossing_point(const Segment& s, const Ring& ring,
                                             const SegmentCrossing& c);

}  // namespace edgeland
