#pragma once
// The order in which the triangulation's sweeps meet vertices (triangulate.cpp).
#include "edgeland/kernel/point.hpp"

namespace edgeland::detail {

// Whether the sweep meets a before b: higher y first, and of equal y the smaller x first (de
// Berg et al., ch. 3). This is the y-order of the plane turned clockwise by an infinitesimal
// angle, so no two vertices are ever level and a horizontal edge runs downward from its left
// end. Orientation tests do not change under rotation: an algorithm that decides with this order
// and orientation() alone runs exactly as on a turned copy of its input in which all y differ.
constexpr bool sweeps_before(Point64 a, Point64 b) noexcept {
  return a.y > b.y || (a.y == b.y && a.x < b.x);
}

}  // namespace edgeland::detail
