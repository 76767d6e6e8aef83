#include "cell_surface.hpp"

#include "chain_tracing.hpp"
#include "solid_boundary.hpp"
#include "surface_segments.hpp"

namespace edgeland::game_detail {

CellSurface cell_surface(const Landscape& world, const Box64& cell, const SurfaceOptions& options) {
  const CellPolygons polygons = read_cell(world, cell);
  return cell_surface(polygons, side_covers(polygons, options.materials), world.world(), options);
}

std::vector<PolygonId> own_ids(const CellPolygons& polygons) {
  std::vector<PolygonId> out;
  out.reserve(polygons.own.size());
  for (const CellPolygon& p : polygons.own) out.push_back(p.id);
  return out;
}

CellSurface cell_surface(const CellPolygons& polygons, SideSpans covers, const Box64& world,
                         const SurfaceOptions& options) {
  const Box64& cell = polygons.box;
  const SolidBoundary solid = solid_boundary(cell, polygons.own, options.materials);
  std::vector<TracedChain> traced = trace_chains(
      surface_segments(polygons, solid, covers, world, options), cell, world, options.border_wall);
  CellSurface out;
  out.ids = own_ids(polygons);
  out.covers = std::move(covers);
  out.ports = port_spans(solid);
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
