#pragma once
// The rules every exported chain keeps (surface_chains.hpp), checked from the definition: enough
// points, one material per segment, no repeated consecutive point, no straight point unless the
// material changes there.
#include <string>

#include "edgeland/game/surface_chains.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland::test {

inline std::string chain_rule_violation(const SurfaceChain& c) {
  const std::size_t n = c.points.size();
  if (n < (c.closed ? 3u : 2u)) return "too few points";
  const std::size_t segments = c.closed ? n : n - 1;
  if (c.materials.size() != segments) return "one material per segment";
  for (std::size_t i = 0; i < segments; ++i)
    if (c.points[i] == c.points[(i + 1) % n]) return "repeated point " + std::to_string(i);
  for (std::size_t i = c.closed ? 0 : 1; i < (c.closed ? n : n - 1); ++i) {
    const std::size_t before = (i + n - 1) % n;
    if (c.materials[before] == c.materials[i] &&
        orientation(c.points[before], c.points[i], c.points[(i + 1) % n]) ==
            Orientation::kCollinear)
      return "straight point " + std::to_string(i);
  }
  if (!c.closed && (c.ghost_prev == c.points.front() || c.ghost_next == c.points.back()))
    return "ghost on the chain's end";
  return "";
}

}  // namespace edgeland::test
