#pragma once
// Meshes of a landscape's own polygons, without validating them again: every polygon a
// landscape holds (its cells, a change set it returned) is valid by its invariant I1, so the
// driver and all_meshes() triangulate without the input check that polygon_mesh() and
// mesh_update() make for polygons of unknown origin (a third of a mesh's cost). Builds with
// assertions check each polygon all the same.
#include "edgeland/game/game_types.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland::game_detail {

// polygon_mesh() of a polygon the landscape holds.
PolygonMesh landscape_mesh(PolygonId id, Material material, const Polygon& polygon);

// mesh_update() of a change set the landscape returned.
MeshUpdate landscape_mesh_update(const ChangeSet& changes);

}  // namespace edgeland::game_detail
