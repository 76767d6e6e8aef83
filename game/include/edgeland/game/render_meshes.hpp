#pragma once
// Render meshes (game/README.md, "Render meshes"): every polygon of the landscape as triangles
// over its own vertices, per polygon id, so that an edit's change set names exactly the meshes
// to drop (its removed ids) and to build (its added polygons). Exact (kernel triangulate()):
// triangles counter-clockwise, none degenerate, interiors disjoint, areas summing exactly to the
// polygon's. Integer coordinates; a renderer converts them to its own units.
#include <vector>

#include "edgeland/game/game_types.hpp"
#include "edgeland/kernel/triangulate.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland {

// The mesh of one landscape polygon. O(n log n).
EDGELAND_EXPORT PolygonMesh polygon_mesh(PolygonId id, Material material, const Polygon& polygon);

// The meshes an edit invalidates and the ones it needs (from its change set alone).
EDGELAND_EXPORT MeshUpdate mesh_update(const ChangeSet& changes);

// The mesh of every polygon, by ascending id. O(N log N).
EDGELAND_EXPORT std::vector<PolygonMesh> all_meshes(const Landscape& world);

}  // namespace edgeland
