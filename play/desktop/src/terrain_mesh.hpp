#pragma once
// The landscape as triangles for SDL_RenderGeometry: one mesh per polygon id, the game layer's
// render mesh (edgeland/game/render_meshes.hpp: the kernel's exact triangulation over the
// polygon's own vertices), built for the polygons a change set adds and dropped for those it
// removes, so an edit costs the meshes of what it changed.
// Pixels are floats: drawing only.
#include <SDL.h>

#include <unordered_map>
#include <vector>

#include "edgeland/game/render_meshes.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::play {

// World units to window pixels, north up.
struct ViewTransform {
  Box64 world;
  int width = 1, height = 1;
  float x(double wx) const {
    return static_cast<float>((wx - static_cast<double>(world.min.x)) * width /
                              static_cast<double>(world.max.x - world.min.x));
  }
  float y(double wy) const {
    return static_cast<float>((static_cast<double>(world.max.y) - wy) * height /
                              static_cast<double>(world.max.y - world.min.y));
  }
  // A window pixel to the world point it shows (integer division: the same point everywhere).
  Point64 world_point(int px, int py) const {
    return {world.min.x + (world.max.x - world.min.x) * px / width,
            world.max.y - (world.max.y - world.min.y) * py / height};
  }
  float scale() const {
    return static_cast<float>(width) / static_cast<float>(world.max.x - world.min.x);
  }
};

class TerrainMesh {
 public:
  explicit TerrainMesh(const ViewTransform& view) : view_(view) {}

  // The game driver's meshes: those dropped deleted, those built added.
  void apply(const MeshUpdate& update);
  void reset(const Landscape& landscape);
  void draw(SDL_Renderer* renderer) const;
  std::size_t triangles() const noexcept { return triangles_; }

 private:
  struct Mesh {
    std::vector<SDL_Vertex> vertices;  // the polygon's own vertices, in pixels, coloured
    std::vector<int> indices;          // three per triangle
  };
  void add(const PolygonMesh& mesh);

  ViewTransform view_;
  std::unordered_map<PolygonId, Mesh> meshes_;
  std::size_t triangles_ = 0;
};

}  // namespace edgeland::play
