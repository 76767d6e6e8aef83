// App's drawing: the terrain meshes, the cell lines and dirty cells, the bodies, the overlay.
#include <array>
#include <cmath>
#include <cstdio>

#include "app.hpp"
#include "edgeland/demo/palette.hpp"
#include "picture.hpp"

namespace edgeland::play {
namespace {

using box2d::BodyKind;
using box2d::SceneBody;

// A filled convex polygon (a body's shape) around `centre`, in pixels.
void fill_convex(SDL_Renderer* renderer, const std::vector<SDL_FPoint>& corners, SDL_Color c) {
  std::vector<SDL_Vertex> vertices;
  for (const SDL_FPoint& p : corners) vertices.push_back({p, c, {0, 0}});
  std::vector<int> fan;
  for (int i = 1; i + 1 < static_cast<int>(corners.size()); ++i) {
    fan.insert(fan.end(), {0, i, i + 1});
  }
  SDL_RenderGeometry(renderer, nullptr, vertices.data(), static_cast<int>(vertices.size()),
                     fan.data(), static_cast<int>(fan.size()));
}

std::vector<SDL_FPoint> body_corners(const box2d::PhysicsScene& physics, const SceneBody& d,
                                     const ViewTransform& view) {
  const EngineVec p = physics.position(d.body);
  const float cx = view.x(p.x), cy = view.y(p.y);
  const float s = static_cast<float>(d.size) * view.scale();
  const float angle = d.body->GetAngle();
  std::vector<SDL_FPoint> corners;
  const int n = d.kind == BodyKind::kBall ? 16 : 4;
  const float first = d.kind == BodyKind::kBall ? 0.0f : 0.785398f;  // a box's corner at 45°
  const float reach = d.kind == BodyKind::kBall ? s : s * 1.41421f;
  for (int k = 0; k < n; ++k) {
    const float a = angle + first + 6.283185f * static_cast<float>(k) / static_cast<float>(n);
    corners.push_back({cx + reach * std::cos(a), cy - reach * std::sin(a)});
  }
  return corners;
}

void outline_boxes(SDL_Renderer* renderer, const std::vector<Box64>& boxes,
                   const ViewTransform& view) {
  for (const Box64& b : boxes) {
    const SDL_FRect r{view.x(static_cast<double>(b.min.x)), view.y(static_cast<double>(b.max.y)),
                      view.x(static_cast<double>(b.max.x)) - view.x(static_cast<double>(b.min.x)),
                      view.y(static_cast<double>(b.min.y)) - view.y(static_cast<double>(b.max.y))};
    SDL_RenderDrawRectF(renderer, &r);
  }
}

}  // namespace

void App::draw() {
  const demo::Rgb sky = demo::material_colour(kEmpty);
  SDL_SetRenderDrawColor(renderer_, sky.r, sky.g, sky.b, 255);
  SDL_RenderClear(renderer_);
  mesh_.draw(renderer_);
  if (show_cells_) draw_cells();
  if (show_dirty_) {
    SDL_SetRenderDrawColor(renderer_, 255, 225, 77, 255);
    outline_boxes(renderer_, dirty_, view_);
  }
  draw_bodies();
  draw_overlay();
}

void App::draw_cells() const {
  std::vector<Box64> cells;
  session_.world().cells_in(session_.world().world(), [&](const CellView& c) {
    cells.push_back(c.box);
    return true;
  });
  SDL_SetRenderDrawBlendMode(renderer_, SDL_BLENDMODE_BLEND);
  SDL_SetRenderDrawColor(renderer_, 255, 255, 255, 80);
  outline_boxes(renderer_, cells, view_);
}

// A debris body: its polygons' meshes in their materials' colours, turned and moved with it
// (the meshes are in landscape coordinates; the body's origin is the island's centroid).
void App::draw_debris(const SceneBody& d) const {
  const EngineVec at = physics_.position(d.body);
  const double c = std::cos(d.body->GetAngle()), s = std::sin(d.body->GetAngle());
  for (const PolygonMesh& mesh : d.meshes) {
    const demo::Rgb colour = demo::material_colour(mesh.material);
    std::vector<SDL_Vertex> vertices;
    for (const Point64& v : mesh.vertices) {
      const double x = static_cast<double>(v.x) - d.centroid.x;
      const double y = static_cast<double>(v.y) - d.centroid.y;
      vertices.push_back({{view_.x(at.x + c * x - s * y), view_.y(at.y + s * x + c * y)},
                          {colour.r, colour.g, colour.b, 255},
                          {0, 0}});
    }
    std::vector<int> indices;
    for (const Triangle& t : mesh.triangles)
      for (const std::uint32_t i : {t.a, t.b, t.c}) indices.push_back(static_cast<int>(i));
    SDL_RenderGeometry(renderer_, nullptr, vertices.data(), static_cast<int>(vertices.size()),
                       indices.data(), static_cast<int>(indices.size()));
  }
}

void App::draw_bodies() const {
  for (const SceneBody& d : physics_.bodies()) {
    if (d.kind == BodyKind::kDebris) {
      draw_debris(d);
      continue;
    }
    const SDL_Color c =
        d.kind == BodyKind::kBall ? SDL_Color{255, 93, 143, 255} : SDL_Color{93, 242, 255, 255};
    fill_convex(renderer_, body_corners(physics_, d, view_), c);
  }
}

// Refreshed every 15 frames: text is drawn with cairo, which is not free.
void App::draw_overlay() {
  if (overlay_ == nullptr || report_.frames % 15 == 0) {
    const LandscapeStats s = session_.world().stats();
    std::array<char, 160> line1{}, line2{}, line3{};
    std::snprintf(line1.data(), line1.size(), "frame %.2f ms  edit %.2f ms  colliders %.2f ms",
                  last_frame_ms_, last_edit_ms_, last_collider_ms_);
    std::snprintf(line2.data(), line2.size(),
                  "polygons %zu  cells %zu  triangles %zu  bodies %zu  edits %llu", s.polygons,
                  s.cells, mesh_.triangles(), physics_.bodies().size(),
                  static_cast<unsigned long long>(report_.edits));
    std::snprintf(line3.data(), line3.size(), "tool %s  radius %lld  material %d  replace %d",
                  tool_.c_str(), static_cast<long long>(radius_), int{material_.value()},
                  int{from_.value()});
    if (overlay_ != nullptr) SDL_DestroyTexture(overlay_);
    overlay_ = text_texture(renderer_, {line1.data(), line2.data(), line3.data()});
  }
  if (overlay_ == nullptr) return;
  int w = 0, h = 0;
  SDL_QueryTexture(overlay_, nullptr, nullptr, &w, &h);
  const SDL_Rect at{6, 6, w, h};
  SDL_RenderCopy(renderer_, overlay_, nullptr, &at);
}

}  // namespace edgeland::play
