#include "terrain_mesh.hpp"

#include "edgeland/demo/palette.hpp"
#include "edgeland/game/render_meshes.hpp"

namespace edgeland::play {

void TerrainMesh::add(const PolygonMesh& from) {
  if (from.material == kEmpty) return;
  const demo::Rgb c = demo::material_colour(from.material);
  Mesh mesh;
  for (const Point64& p : from.vertices) {
    const SDL_FPoint at{view_.x(static_cast<double>(p.x)), view_.y(static_cast<double>(p.y))};
    mesh.vertices.push_back({at, {c.r, c.g, c.b, 255}, {0, 0}});
  }
  for (const Triangle& t : from.triangles) {
    for (const std::uint32_t i : {t.a, t.b, t.c}) mesh.indices.push_back(static_cast<int>(i));
  }
  triangles_ += mesh.indices.size() / 3;
  meshes_[from.id] = std::move(mesh);
}

void TerrainMesh::apply(const MeshUpdate& update) {
  for (const PolygonId id : update.dropped) {
    const auto it = meshes_.find(id);
    if (it == meshes_.end()) continue;
    triangles_ -= it->second.indices.size() / 3;
    meshes_.erase(it);
  }
  for (const PolygonMesh& mesh : update.built) add(mesh);
}

void TerrainMesh::reset(const Landscape& landscape) {
  meshes_.clear();
  triangles_ = 0;
  for (const PolygonMesh& mesh : all_meshes(landscape)) add(mesh);
}

void TerrainMesh::draw(SDL_Renderer* renderer) const {
  for (const auto& [id, mesh] : meshes_) {
    SDL_RenderGeometry(renderer, nullptr, mesh.vertices.data(),
                       static_cast<int>(mesh.vertices.size()), mesh.indices.data(),
                       static_cast<int>(mesh.indices.size()));
  }
}

}  // namespace edgeland::play
