#pragma once
// The outward normal of a ring edge: what the landscape's ray hits report, and what an engine
// turns into a surface normal. Exact and not normalised (formulas::outward_normal, theorem
// outward_normal_int64: each component is a coordinate difference, below 2^33 in magnitude).
#include <cstdint>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"
#include "edgeland/kernel/point.hpp"

namespace edgeland {

// The normal of edge a -> b (in range) pointing out of a counter-clockwise ring, whose interior
// lies left of the edge: (b.y - a.y, -(b.x - a.x)). O(1).
inline Point64 outward_normal(Point64 a, Point64 b) noexcept {
  using D = arith::Checked<std::int64_t>;
  const formulas::Normal<D> n = formulas::outward_normal<D>(a.x, a.y, b.x, b.y);
  return {n.x.v, n.y.v};
}

}  // namespace edgeland
