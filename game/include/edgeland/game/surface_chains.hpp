#pragma once
// The collision surface of a landscape as chains of edges (game/README.md, "Surface chains"):
// what a physics engine needs of the terrain. Integer and exact, engine-neutral; the Box2D
// adapter (adapters/box2d) only converts units.
//
// THE SURFACE is the boundary between solid and non-solid material (PhysicsMaterials): an edge
// shared by two solid pieces (a cell line, a hole-splitting bridge, the border between two solid
// materials) is never part of it, so a body sliding along the terrain meets no seam. The world
// border is not part of it either, unless `border_wall` is set: then the border is a wall around
// the world's non-solid parts.
//
// CHAINS run with solid on their LEFT: counter-clockwise around solid, clockwise around the
// holes in it. One-sided collision in Box2D 2.4/3 (the edge normal points right) then faces the
// empty side. A chain holds at least 2 points (a closed one at least 3, its first point not
// repeated at the end), no two consecutive points equal, and no three consecutive points on one
// line unless the material changes there (a point is kept on purpose where one segment's
// material differs from the next's).
//
// PER CELL. surface_chains() cuts the surface at the landscape's cell lines: each chain lies in
// one cell and carries its two GHOST vertices, the surface points just before its first and
// just after its last point, taken across the cell line from the neighbour (Box2D 2.4
// b2ChainShape::CreateChain(v, n, prev, next), Box2D 3 chain segments, Godot segments). So one
// cell's chains can be replaced without touching its neighbours' and the joint stays smooth.
// Where the surface meets the world border (no wall), the ghost continues the last segment in
// a straight line. A closed chain's ghosts are its own last and first point.
//
// Exact: every point is a vertex of a landscape polygon or a corner where a cell line crosses
// the surface; nothing is rounded here.
#include <cstdint>
#include <vector>

#include "edgeland/game/game_types.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland {

// The surface of every cell, cell by cell in tree order (within a cell: open chains in order of
// their first point, then closed ones in order of their smallest point). O(N log N) for N
// vertices.
EDGELAND_EXPORT std::vector<SurfaceChain> surface_chains(const Landscape& world,
                                                         const SurfaceOptions& options = {});

// The surface as whole loops, joined across cell lines, for a static export: closed loops,
// and open chains that end at the world border (not with a wall). `cell` is the world box.
// O(N log N).
EDGELAND_EXPORT std::vector<SurfaceChain> surface_loops(const Landscape& world,
                                                        const SurfaceOptions& options = {});

}  // namespace edgeland
