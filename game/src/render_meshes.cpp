#include "edgeland/game/render_meshes.hpp"

#include <algorithm>

namespace edgeland {

PolygonMesh polygon_mesh(PolygonId id, Material material, const Polygon& polygon) {
  return {id, material, polygon, triangulate(polygon)};
}

MeshUpdate mesh_update(const ChangeSet& changes) {
  MeshUpdate out;
  out.dropped = changes.removed;
  for (const ChangeSet::Added& a : changes.added)
    out.built.push_back(polygon_mesh(a.id, a.material, a.polygon));
  return out;
}

std::vector<PolygonMesh> all_meshes(const Landscape& world) {
  std::vector<PolygonMesh> out;
  world.polygons_in(world.world(), [&](const PolygonView& v) {
    out.push_back(polygon_mesh(v.id, v.material, *v.polygon));
    return true;
  });
  std::sort(out.begin(), out.end(),
            [](const PolygonMesh& l, const PolygonMesh& r) { return l.id < r.id; });
  return out;
}

}  // namespace edgeland
