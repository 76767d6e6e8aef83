#include "cell_surface.hpp"

#include "chain_tracing.hpp"
#include "solid_boundary.hpp"
#include "surface_segments.hpp"

namespace edgeland::game_detail {

CellSurface cell_surface(const Landscape& world, const Box64& cell, const SurfaceOptions& options) {
  const CellPolygons polygons = read_cell(world, cell);
  const SolidBoundary solid = solid_boundary(cell, polygons.own, options.materials);
  std::vector<TracedChain> traced =
      trace_chains(surface_segments(polygons, solid, world.world(), options), cell, world.world(),
                   options.border_wall);
  CellSurface out;
  for (const CellPolygon& p : polygons.own) out.ids.push_back(p.id);
  out.chains.reserve(traced.size());
  for (TracedChain& t : traced) {
    SurfaceChain c;
    c.points = std::move(t.points);
    c.materials = std::move(t.materials);
    c.closed = t.closed;
    c.cell = cell;
    if (c.closed) {
      c.ghost_prev = c.points.back();
      c.ghost_next = c.points.front();
    }
    out.chains.push_back(std::move(c));
  }
  return out;
}

}  // namespace edgeland::game_detail
