#pragma once
// Stages 1-3 of the surface for one cell: solid boundary, surface segments, chains; everything
// but the ghosts, which need the neighbours' chains (ghosts.hpp).
#include <vector>

#include "cell_polygons.hpp"
#include "edgeland/game/surface_chains.hpp"
#include "surface_segments.hpp"

namespace edgeland::game_detail {

struct CellSurface {
  std::vector<SurfaceChain> chains;  // ghosts unset (open) or set to their own ends (closed)
  std::vector<PolygonId> ids;        // the cell's polygons, in the cell's order
  SideSpans covers;                  // what stage 2 read from the neighbours
  SideSpans ports;                   // what the neighbours' covers read of this cell
};

// O(n log n) in the edges of the cell and of its neighbours along its sides.
CellSurface cell_surface(const Landscape& world, const Box64& cell, const SurfaceOptions& options);

// The same from the cell as read (read_cell) and its covers (side_covers).
CellSurface cell_surface(const CellPolygons& polygons, SideSpans covers, const Box64& world,
                         const SurfaceOptions& options);

// The ids of the cell's own polygons, in the cell's order.
std::vector<PolygonId> own_ids(const CellPolygons& polygons);

}  // namespace edgeland::game_detail
