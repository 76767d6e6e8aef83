#pragma once
// Stages 1-3 of the surface for one cell: solid boundary, surface segments, chains; everything
// but the ghosts, which need the neighbours' chains (ghosts.hpp).
#include <vector>

#include "edgeland/game/surface_chains.hpp"

namespace edgeland::game_detail {

struct CellSurface {
  std::vector<SurfaceChain> chains;  // ghosts unset (open) or set to their own ends (closed)
  std::vector<PolygonId> ids;        // the cell's polygons, in the cell's order
};

// O(n log n) in the edges of the cell and of its neighbours along its sides.
CellSurface cell_surface(const Landscape& world, const Box64& cell, const SurfaceOptions& options);

}  // namespace edgeland::game_detail
