#pragma once
// Stage 3 of triangulate(): one monotone piece into triangles.
#include <cstdint>
#include <span>
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/triangulate.hpp"

namespace edgeland::detail {

// Appends the m - 2 triangles of a face of m vertices (indices into `polygon`, counter-
// clockwise) that is monotone in the sweep order (sweep_order.hpp): de Berg et al., ch. 3.3,
// TriangulateMonotonePolygon. Every triangle is counter-clockwise with positive area, also when
// the face has straight vertices (kernel/README.md: why the stack never yields a flat one).
// O(m).
void triangulate_monotone(const Polygon& polygon, std::span<const std::uint32_t> face,
                          std::vector<Triangle>& out);

}  // namespace edgeland::detail
