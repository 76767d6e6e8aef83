#pragma once
// The desktop demo (play/desktop/README.md): a landscape under the mouse, with tools, undo/redo,
// save/load, balls and boxes rolling on it (Box2D) and an overlay, driven by input events that
// come from SDL or from a recorded script alike, so a scripted session is the same program as a
// played one.
#include <SDL.h>

#include <cstdint>
#include <string>
#include <vector>

#include "edgeland/play/session.hpp"
#include "input_script.hpp"
#include "physics_scene.hpp"
#include "terrain_mesh.hpp"

namespace edgeland::play {

struct AppOptions {
  Box64 world{{0, 0}, {4096, 2048}};
  std::uint64_t seed = 1;  // the `edgeland demo` world's seed
  int width = 1024, height = 512;
  double units_per_metre = 32;
  std::string save_file = "edgeland-play.save";  // F5 writes it, F9 reads it
};

// What a session did and what its checks found.
struct AppReport {
  std::uint64_t frames = 0, edits = 0, refused = 0, undos = 0, redos = 0;
  std::uint64_t bodies_dropped = 0, bodies_buried = 0;
  std::uint64_t inside_solid = 0;  // ball and box centres found in solid material after a step
  std::uint64_t islands_detached = 0;
  std::uint64_t islands_left = 0;  // islands still in the landscape after an edit settled
  std::uint64_t saves = 0, loads = 0, loads_matching_save = 0;
  double frame_ms_total = 0, frame_ms_max = 0, edit_ms_total = 0, collider_ms_total = 0;
};

class App {
 public:
  App(SDL_Renderer* renderer, const AppOptions& options);
  ~App();
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  void handle(const InputEvent& event);
  // One physics step and its checks.
  void step();
  void draw();
  // Marks the end of a frame whose work took `ms`.
  void end_frame(double ms);

  const Landscape& world() const noexcept { return session_.world(); }
  const box2d::PhysicsScene& physics() const noexcept { return physics_; }
  const AppReport& report() const noexcept { return report_; }
  const TerrainMesh& mesh() const noexcept { return mesh_; }

 private:
  void use_tool(Point64 from, Point64 to);
  void press_key(const std::string& key);
  void take(const GameUpdate& update, bool may_bury);
  void take_world(const GameUpdate& update);  // after undo, redo, load
  void save();
  void load();
  void bury();
  void draw_bodies() const;
  void draw_debris(const box2d::SceneBody& debris) const;
  void draw_cells() const;
  void draw_overlay();

  SDL_Renderer* renderer_;
  AppOptions options_;
  ViewTransform view_;
  Session session_;
  TerrainMesh mesh_;
  box2d::PhysicsScene physics_;
  AppReport report_;
  // Tool state.
  std::string tool_ = "explosion";
  Material material_ = 3, from_ = 2;
  std::int64_t radius_ = 64;
  Point64 mouse_, stroke_;
  bool pressed_ = false;
  bool show_cells_ = false, show_dirty_ = false;
  std::vector<Box64> dirty_;
  std::uint64_t saved_hash_ = 0;
  // Overlay.
  SDL_Texture* overlay_ = nullptr;
  double last_frame_ms_ = 0, last_edit_ms_ = 0, last_collider_ms_ = 0;
};

}  // namespace edgeland::play
