#pragma once
// A brute-force reference for the collision surface (game/include/edgeland/game/
// surface_chains.hpp), written from its definition and sharing no code with game/: every edge of
// every solid polygon of the landscape, all cells together, directed with its polygon on the
// left; on each line, what runs one way and is not covered by something running the other way is
// surface; minus the world border; plus, with a wall, the border where no solid lies on it.
// Surfaces are compared as sets of directed intervals per line, merged where they continue in the
// same material, so any cutting into segments and chains compares equal.
#include <map>
#include <tuple>
#include <vector>

#include "edgeland/game/surface_chains.hpp"

namespace edgeland::test {

// A line as a reduced direction (pointing to +x, or +y when vertical) and its offset.
struct OracleLine {
  std::int64_t dx = 0, dy = 0;
  Int128 offset = 0;
  friend bool operator<(const OracleLine& l, const OracleLine& r) {
    return std::tie(l.dx, l.dy, l.offset) < std::tie(r.dx, r.dy, r.offset);
  }
  friend bool operator==(const OracleLine&, const OracleLine&) = default;
};

// A run of surface along a line: positions lo < hi (x, or y on a vertical line).
struct Run {
  std::int64_t lo = 0, hi = 0;
  bool forward = true;  // runs in the line's direction
  Material material = kEmpty;
  friend bool operator==(const Run&, const Run&) = default;
};

using SurfaceMap = std::map<OracleLine, std::vector<Run>>;

// The reference surface of a landscape.
SurfaceMap surface_brute(const Landscape& world, const SurfaceOptions& options);
// The surface that chains describe.
SurfaceMap surface_of(const std::vector<SurfaceChain>& chains);
// The first difference between two surfaces, as text; empty when equal.
std::string surface_difference(const SurfaceMap& expected, const SurfaceMap& actual);

}  // namespace edgeland::test
