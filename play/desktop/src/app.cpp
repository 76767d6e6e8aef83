#include "app.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

#include "edgeland/demo/landscape.hpp"
#include "picture.hpp"

namespace edgeland::play {
namespace {

using box2d::BodyKind;
using box2d::SceneBody;
using demo::kWater;

bool solid(Material m) { return m != kEmpty && m != kWater; }

// The balls bounce a little; the boxes fall turned, so that they tumble.
constexpr box2d::BodySurface kBallSurface{.friction = 0.4f, .restitution = 0.2f};
constexpr float kBoxAngle = 0.3f;

// Water is no obstacle; the world's border is a wall, so that nothing rolls out of the world.
GameOptions game_options() {
  GameOptions options;
  options.surface.materials.set_solid(kWater, false);
  options.surface.border_wall = true;
  return options;
}

// Box2D in metres of `units_per_metre` world units, from the world box's corner.
box2d::TerrainOptions terrain_options(double units_per_metre) {
  box2d::TerrainOptions options;
  options.units_per_metre = units_per_metre;
  return options;
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

std::optional<ToolKind> tool_kind(const std::string& name) {
  if (name == "explosion") return ToolKind::kExplosion;
  if (name == "digger") return ToolKind::kDigger;
  if (name == "fill") return ToolKind::kFill;
  if (name == "water") return ToolKind::kWater;
  if (name == "replace") return ToolKind::kReplace;
  return std::nullopt;
}

bool is_stroke_tool(const std::string& name) {
  return name == "digger" || name == "fill" || name == "water" || name == "replace";
}

}  // namespace

App::App(SDL_Renderer* renderer, const AppOptions& options)
    : renderer_(renderer),
      options_(options),
      view_{options.world, options.width, options.height},
      session_(demo::demo_landscape(options.world, options.seed), game_options()),
      mesh_(view_),
      physics_(session_.game(), terrain_options(options.units_per_metre)) {
  mesh_.reset(session_.world());
  take(session_.settle(), true);  // the islands the world starts with fall
}

App::~App() {
  if (overlay_ != nullptr) SDL_DestroyTexture(overlay_);
}

// --- input -------------------------------------------------------------------------------------

void App::handle(const InputEvent& e) {
  const Point64 at = view_.world_point(e.x, e.y);
  switch (e.kind) {
    case InputKind::kTool:
      tool_ = e.name;
      break;
    case InputKind::kMaterial:
      material_ = static_cast<Material>(std::clamp(e.x, 1, 255));
      break;
    case InputKind::kFrom:
      from_ = static_cast<Material>(std::clamp(e.x, 0, 255));
      break;
    case InputKind::kRadius:
      radius_ = std::max<std::int64_t>(kMinToolRadius, e.x);
      break;
    case InputKind::kWheel:
      radius_ = std::max<std::int64_t>(
          kMinToolRadius,
          static_cast<std::int64_t>(static_cast<double>(radius_) * std::pow(1.15, e.x)));
      break;
    case InputKind::kDown:
      pressed_ = true;
      mouse_ = stroke_ = at;
      use_tool(at, at);
      break;
    case InputKind::kMove: {
      mouse_ = at;
      const Int128 dx = at.x - stroke_.x, dy = at.y - stroke_.y;
      if (pressed_ && is_stroke_tool(tool_) &&
          4 * (dx * dx + dy * dy) >= Int128{radius_} * radius_) {
        use_tool(stroke_, at);
        stroke_ = at;
      }
      break;
    }
    case InputKind::kUp:
      mouse_ = at;
      pressed_ = false;
      break;
    case InputKind::kKey:
      press_key(e.name);
      break;
  }
}

void App::use_tool(Point64 from, Point64 to) {
  if (tool_ == "ball" || tool_ == "box") {
    if (tool_ == "ball")
      physics_.drop_ball(to, 24, kBallSurface);
    else
      physics_.drop_box(to, 20, kBoxAngle);
    ++report_.bodies_dropped;
    return;
  }
  const std::optional<ToolKind> kind = tool_kind(tool_);
  if (!kind) return;
  const ToolEdit edit{.tool = *kind,
                      .from = from,
                      .to = to,
                      .radius = radius_,
                      .material = *kind == ToolKind::kWater ? kWater : material_,
                      .from_material = from_};
  const auto start = std::chrono::steady_clock::now();
  std::optional<GameUpdate> update;
  try {
    update = session_.apply(edit);
  } catch (const Error&) {
    ++report_.refused;  // the world is as it was (strong guarantee)
    return;
  }
  last_edit_ms_ = ms_since(start);
  report_.edit_ms_total += last_edit_ms_;
  ++report_.edits;
  take(*update, *kind != ToolKind::kExplosion && *kind != ToolKind::kDigger);
}

void App::press_key(const std::string& key) {
  if (key == "ctrl+z") {
    if (const std::optional<GameUpdate> u = session_.undo()) {
      ++report_.undos;
      take_world(*u);
    }
  } else if (key == "ctrl+y") {
    if (const std::optional<GameUpdate> u = session_.redo()) {
      ++report_.redos;
      take_world(*u);
    }
  } else if (key == "f5") {
    save();
  } else if (key == "f9") {
    load();
  } else if (key == "c") {
    show_cells_ = !show_cells_;
  } else if (key == "d") {
    show_dirty_ = !show_dirty_;
  } else if (key == "b" || key == "x") {
    if (key == "b")
      physics_.drop_ball(mouse_, 24, kBallSurface);
    else
      physics_.drop_box(mouse_, 20, kBoxAngle);
    ++report_.bodies_dropped;
  }
}

// --- the world's changes -----------------------------------------------------------------------

// The update's meshes, chains and debris (the game driver's, translated).
void App::take(const GameUpdate& update, bool may_bury) {
  const auto start = std::chrono::steady_clock::now();
  mesh_.apply(update.meshes);
  physics_.apply(update);
  last_collider_ms_ = ms_since(start);
  report_.collider_ms_total += last_collider_ms_;
  dirty_ = update.changes.cells;
  report_.islands_detached += update.debris.size();
  report_.islands_left += update.debris_waiting;
  if (may_bury) bury();
}

// Undo, redo and load put the islands that were detached back into the landscape: their debris
// goes, and those islands fall again with the update.
void App::take_world(const GameUpdate& update) {
  physics_.remove_bodies([](const SceneBody& b) { return b.kind == BodyKind::kDebris; });
  take(update, true);
}

// A body whose centre an edit filled is buried: the game removes it.
void App::bury() {
  report_.bodies_buried += physics_.remove_bodies([&](const SceneBody& b) {
    return b.kind != BodyKind::kDebris &&
           solid(session_.world().material_at(physics_.centre(b.body)));
  });
}

void App::save() {
  std::ofstream out(options_.save_file, std::ios::binary | std::ios::trunc);
  session_.world().save(out);
  if (!out.flush()) return;
  saved_hash_ = session_.world().state_hash();
  ++report_.saves;
}

void App::load() {
  std::ifstream in(options_.save_file, std::ios::binary);
  if (!in) return;
  try {
    Landscape loaded = Landscape::load(in);
    loaded.start_log();  // the log goes on from the loaded world (a world line and fills)
    ++report_.loads;
    if (loaded.state_hash() == saved_hash_) ++report_.loads_matching_save;
    take_world(session_.reset(std::move(loaded)));
  } catch (const LoadError&) {
    ++report_.refused;
  }
}

// --- frames ------------------------------------------------------------------------------------

// A step, the bodies that fell 8 m below the world's floor gone, then the check.
void App::step() {
  physics_.step(1.0f / 60.0f);
  physics_.remove_bodies([](const SceneBody& b) { return b.body->GetPosition().y <= -8.0f; });
  report_.inside_solid += physics_.centres_in_solid().size();
}

void App::end_frame(double ms) {
  ++report_.frames;
  last_frame_ms_ = ms;
  report_.frame_ms_total += ms;
  report_.frame_ms_max = std::max(report_.frame_ms_max, ms);
}

}  // namespace edgeland::play
