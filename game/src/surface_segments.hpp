#pragma once
// Stage 2 of the surface (game/README.md): a cell's surface segments. Its free pieces, the parts
// of its ports that no solid of a neighbour covers from across the side (a port on the world
// border is never surface), and, with a border wall, the parts of its world-border sides that
// its own solid does not cover (solid, the outside, on their left).
#include <vector>

#include "edgeland/game/surface_chains.hpp"
#include "solid_boundary.hpp"

namespace edgeland::game_detail {

struct SurfaceSegment {
  Point64 a, b;               // solid on the left
  Material material = kEmpty;  // that solid's material (0 for a wall)
};

// O(n log n) in the cell's and its neighbours' edges along its sides.
std::vector<SurfaceSegment> surface_segments(const CellPolygons& cell, const SolidBoundary& solid,
                                             const Box64& world, const SurfaceOptions& options);

// Whether the box's side lies on the world box's border.
bool on_world_border(const Box64& box, Side side, const Box64& world);

}  // namespace edgeland::game_detail
