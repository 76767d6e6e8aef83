#include "edgeland/game/render_meshes.hpp"

#include <algorithm>

#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/triangulation.hpp"
#include "landscape_meshes.hpp"

namespace edgeland {
namespace game_detail {

namespace {

// The meshes a change set drops and builds, each built one made by `mesh_of`.
template <class MeshOf>
MeshUpdate update_of(const ChangeSet& changes, MeshOf mesh_of) {
  MeshUpdate out;
  out.dropped = changes.removed;
  for (const ChangeSet::Added& a : changes.added)
    out.built.push_back(mesh_of(a.id, a.material, a.polygon));
  return out;
}

}  // namespace

PolygonMesh landscape_mesh(PolygonId id, Material material, const Polygon& polygon) {
  if constexpr (EDGELAND_ASSERTS_ENABLED) detail::require_valid_polygon(polygon);
  return {id, material, polygon, detail::triangulate_valid(polygon)};
}

MeshUpdate landscape_mesh_update(const ChangeSet& changes) {
  return update_of(changes, landscape_mesh);
}

}  // namespace game_detail

PolygonMesh polygon_mesh(PolygonId id, Material material, const Polygon& polygon) {
  return {id, material, polygon, triangulate(polygon)};
}

MeshUpdate mesh_update(const ChangeSet& changes) {
  return game_detail::update_of(changes, polygon_mesh);
}

std::vector<PolygonMesh> all_meshes(const Landscape& world) {
  std::vector<PolygonMesh> out;
  world.polygons_in(world.world(), [&](const PolygonView& v) {
    out.push_back(game_detail::landscape_mesh(v.id, v.material, *v.polygon));
    return true;
  });
  std::sort(out.begin(), out.end(),
            [](const PolygonMesh& l, const PolygonMesh& r) { return l.id < r.id; });
  return out;
}

}  // namespace edgeland
