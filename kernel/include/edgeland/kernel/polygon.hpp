#pragma once
// The kernel's polygon model (thesis chapter 2).
//
// A Polygon is one closed ring given by its vertices without repeating the first one at the
// end. Valid polygons (see validate.hpp) are strictly simple, counter-clockwise, have at
// least 3 vertices and nonzero area, and no holes: a region with holes is represented as
// several hole-free polygons (thesis 3.6.3). A PolygonSet is a list of valid polygons whose
// interiors are pairwise disjoint; their boundaries may touch along edges or at vertices.
#include <cstddef>
#include <vector>

#include "edgeland/kernel/point.hpp"

namespace edgeland {

using Ring = std::vector<Point64>;
using Polygon = std::vector<Point64>;
using PolygonSet = std::vector<Polygon>;

// Edge i of a ring goes from vertex i to vertex (i + 1) mod n.
struct Segment {
  Point64 a;
  Point64 b;
  friend constexpr bool operator==(const Segment&, const Segment&) = default;
};

inline Segment ring_edge(const Ring& ring, std::size_t i) {
  return {ring[i], ring[(i + 1) % ring.size()]};
}

}  // namespace edgeland
