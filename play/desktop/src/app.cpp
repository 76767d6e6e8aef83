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

using demo::kWater;

bool solid(Material m) { return m != kEmpty && m != kWater; }

// Water is no obstacle; the world's border is a wall, so that nothing rolls out of the world.
SurfaceOptions surface_options() {
  SurfaceOptions options;
  options.materials.set_solid(kWater, false);
  options.border_wall = true;
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
      session_(demo::demo_landscape(options.world, options.seed)),
      mesh_(view_),
      physics_(session_.world(), options.units_per_metre, surface_options()),
      islands_(session_.world(), surface_options().materials) {
  take_world();
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
      physics_.drop_ball(to, 24);
    else
      physics_.drop_box(to, 20);
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
  ChangeSet changes;
  try {
    changes = session_.apply(edit);
  } catch (const Error&) {
    ++report_.refused;  // the world is as it was (strong guarantee)
    return;
  }
  last_edit_ms_ = ms_since(start);
  report_.edit_ms_total += last_edit_ms_;
  ++report_.edits;
  take(changes, *kind != ToolKind::kExplosion && *kind != ToolKind::kDigger);
}

void App::press_key(const std::string& key) {
  if (key == "ctrl+z" && session_.undo()) {
    ++report_.undos;
    take_world();
  } else if (key == "ctrl+y" && session_.redo()) {
    ++report_.redos;
    take_world();
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
      physics_.drop_ball(mouse_, 24);
    else
      physics_.drop_box(mouse_, 20);
    ++report_.bodies_dropped;
  }
}

// --- the world's changes -----------------------------------------------------------------------

void App::take(const ChangeSet& changes, bool may_bury) {
  const auto start = std::chrono::steady_clock::now();
  mesh_.apply(changes);
  physics_.apply(session_.world(), changes);
  last_collider_ms_ = ms_since(start);
  report_.collider_ms_total += last_collider_ms_;
  dirty_ = changes.cells;
  settle(islands_.update(session_.world(), changes));
  if (may_bury) bury();
}

// Undo, redo and load put the islands that were detached back into the landscape: their debris
// goes, and the trackers see the whole world again.
void App::take_world() {
  mesh_.reset(session_.world());
  physics_.reset(session_.world());
  physics_.remove_debris();
  dirty_.clear();
  settle(islands_.resync(session_.world()));
  bury();
}

// Every island falls: detached from the landscape as one edit (given to the trackers like any
// other), it becomes a dynamic body. Detaching one island can re-cut the cells of another, which
// is then stale and comes back re-cut from the tracker (game/islands.hpp).
void App::settle(std::vector<Island> pending) {
  Landscape& world = session_.world();
  while (!pending.empty()) {
    const Island island = std::move(pending.back());
    pending.pop_back();
    std::optional<DetachedIsland> detached;
    try {
      detached = detach(world, island);
    } catch (const StaleIsland&) {
      continue;  // re-cut by another detach: the tracker reports it again
    } catch (const Error&) {
      continue;  // refused (a bug of the game layer): it stays in the landscape, counted as left
    }
    mesh_.apply(detached->changes);
    physics_.apply(world, detached->changes);
    for (Island& again : islands_.update(world, detached->changes)) {
      pending.push_back(std::move(again));
    }
    physics_.add_debris(*detached);
    ++report_.islands_detached;
  }
  report_.islands_left += islands_.island_count();
}

// A body whose centre an edit filled is buried: the game removes it.
void App::bury() {
  report_.bodies_buried +=
      physics_.remove_buried([&](Point64 p) { return solid(session_.world().material_at(p)); });
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
    session_.reset(std::move(loaded));
    take_world();
  } catch (const LoadError&) {
    ++report_.refused;
  }
}

// --- frames ------------------------------------------------------------------------------------

void App::step() {
  physics_.step(1.0 / 60.0);
  for (const DynamicBody& body : physics_.bodies()) {
    if (body.kind == BodyKind::kDebris) continue;  // its centroid may lie outside its own shape
    if (solid(session_.world().material_at(physics_.centre(body)))) ++report_.inside_solid;
  }
}

void App::end_frame(double ms) {
  ++report_.frames;
  last_frame_ms_ = ms;
  report_.frame_ms_total += ms;
  report_.frame_ms_max = std::max(report_.frame_ms_max, ms);
}

}  // namespace edgeland::play
