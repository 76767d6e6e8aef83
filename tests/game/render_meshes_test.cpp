// Render meshes (render_meshes.hpp): a mirror kept from change sets alone equals the meshes of
// every polygon after every edit, and every mesh covers its polygon exactly.
#include "edgeland/game/render_meshes.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <map>

#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/validate.hpp"
#include "landscape_cases.hpp"

namespace edgeland::test {
namespace {

// The triangles of a mesh are counter-clockwise with positive area, pairwise interior-disjoint
// (a valid set), and their areas add up to the polygon's.
std::string mesh_problem(const PolygonMesh& m) {
  PolygonSet triangles;
  Int128 sum = 0;
  for (const Triangle& t : m.triangles) {
    const Polygon tri{m.vertices[t.a], m.vertices[t.b], m.vertices[t.c]};
    if (twice_signed_area(tri) <= 0) return "a triangle is not counter-clockwise";
    sum += twice_signed_area(tri);
    triangles.push_back(tri);
  }
  if (sum != twice_signed_area(m.vertices)) return "the areas do not add up";
  if (m.triangles.size() + 2 != m.vertices.size()) return "not n - 2 triangles";
  if (!validate(triangles).ok()) return "triangles overlap";
  return "";
}

RC_GTEST_PROP(RenderMeshesProperty, MirrorOfChangeSetsEqualsEveryPolygonsMesh, ()) {
  const LandscapeCase c = *landscape_case(8);
  Landscape world(c.world, c.fill, c.config);
  std::map<PolygonId, PolygonMesh> mirror;
  for (PolygonMesh& m : all_meshes(world)) mirror.emplace(m.id, std::move(m));
  for (const LandscapeEdit& e : c.edits) {
    const MeshUpdate u = mesh_update(apply(world, e));
    for (PolygonId id : u.dropped) RC_ASSERT(mirror.erase(id) == 1u);
    for (const PolygonMesh& m : u.built) {
      const std::string problem = mesh_problem(m);
      if (!problem.empty()) RC_FAIL(problem);
      RC_ASSERT(mirror.emplace(m.id, m).second);
    }
  }
  std::map<PolygonId, PolygonMesh> expected;
  for (PolygonMesh& m : all_meshes(world)) expected.emplace(m.id, std::move(m));
  RC_ASSERT(mirror == expected);
  world.polygons_in(world.world(), [&](const PolygonView& v) {
    RC_ASSERT(mirror.at(v.id).vertices == *v.polygon);
    RC_ASSERT(mirror.at(v.id).material == v.material);
    return true;
  });
}

}  // namespace
}  // namespace edgeland::test
