#pragma once
// The exact reference for normalize(): the region where the winding number of arbitrary
// rings satisfies a fill rule, computed from a vertical slab decomposition in exact rationals
// and handed to CGAL as trapezoids (so the contract oracle can ask it the usual questions).
//
// Between two consecutive event abscissas (vertices and pairwise crossings) no two segments
// cross, so the non-vertical segments spanning the slab are totally ordered by height, and the
// winding number just above a segment is the sum over the segments below of +1 (segment
// running in +x) or -1 (running in -x): a counter-clockwise ring runs +x along its bottom.
// Each maximal run of filled gaps in a slab is one trapezoid. Written from the definition of
// the winding number; shares nothing with the library's labeling.
#include <vector>

#include "cgal_reference.hpp"
#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::test {

struct FilledRegion {
  ExactRegion region;
  Rational trapezoid_area;  // sum of the trapezoid areas: must equal region.area()
  std::size_t trapezoids = 0;
};

// O(s^2 + e s log s) for s segments and e events. Rings with fewer than 2 distinct points
// contribute nothing; repeated points, spikes and zero-area parts are allowed.
FilledRegion filled_region(const std::vector<Ring>& rings, FillRule rule);

// The region import_polygons reads OGC polygons as (clip.hpp): each ring stands for the points
// it winds around (non-zero), exteriors count +1 and holes -1, filled where the sum of the
// rings winding around a point is positive. Same slabs, with a winding number per ring.
FilledRegion ogc_region(const std::vector<std::vector<Ring>>& polygons);

}  // namespace edgeland::test
