#include "web_world.hpp"

#include <algorithm>
#include <chrono>

#include "edgeland/demo/landscape.hpp"
#include "edgeland/io/landscape_log.hpp"
#include "edgeland/io/landscape_replay.hpp"

namespace edgeland::play {
namespace {

using demo::kWater;

// Water is no obstacle; the world's border is a wall, so that nothing rolls out of the world.
// The page draws polygons and debris from its own triangulation.
GameOptions game_options() {
  GameOptions options;
  options.surface.materials.set_solid(kWater, false);
  options.surface.border_wall = true;
  options.meshes = false;
  return options;
}

Landscape starting_world(const Box64& box, Material fill, std::uint64_t seed) {
  if (seed > 0) return demo::demo_landscape(box, seed);
  Landscape world(box, fill);
  world.start_log();
  return world;
}

void add_box(std::vector<std::int32_t>& out, const Box64& b) {
  for (const std::int64_t c : {b.min.x, b.min.y, b.max.x, b.max.y}) {
    out.push_back(static_cast<std::int32_t>(c));
  }
}

void add_point(std::vector<std::int32_t>& out, Point64 p) {
  out.push_back(static_cast<std::int32_t>(p.x));
  out.push_back(static_cast<std::int32_t>(p.y));
}

void add_polygon(WebUpdate& update, PolygonId id, Material material, const Polygon& polygon) {
  update.ids.push_back(static_cast<double>(id));
  update.materials.push_back(material.value());
  for (const Point64& p : polygon) add_point(update.xy, p);
  update.offsets.push_back(static_cast<std::uint32_t>(update.xy.size() / 2));
}

void add_chain(WebUpdate& update, ChainId id, const SurfaceChain& chain) {
  update.chain_ids.push_back(static_cast<double>(id));
  update.chain_closed.push_back(chain.closed ? 1 : 0);
  for (const Point64& p : chain.points) add_point(update.chain_xy, p);
  update.chain_offsets.push_back(static_cast<std::uint32_t>(update.chain_xy.size() / 2));
  add_point(update.chain_ghosts, chain.ghost_prev);
  add_point(update.chain_ghosts, chain.ghost_next);
}

// Debris as its convex pieces around its exact centroid (at most 8 vertices each: what a Box2D
// or planck.js polygon shape takes).
void add_debris(WebUpdate& update, const Debris& debris) {
  const double cx =
      static_cast<double>(debris.centroid.x_num) / static_cast<double>(debris.centroid.den);
  const double cy =
      static_cast<double>(debris.centroid.y_num) / static_cast<double>(debris.centroid.den);
  update.debris_centroids.insert(update.debris_centroids.end(), {cx, cy});
  for (const DebrisPiece& piece : debris.pieces) {
    update.piece_materials.push_back(piece.material.value());
    for (const Point64& p : piece.polygon) {
      update.piece_xy.push_back(static_cast<double>(p.x) - cx);
      update.piece_xy.push_back(static_cast<double>(p.y) - cy);
    }
    update.piece_offsets.push_back(static_cast<std::uint32_t>(update.piece_xy.size() / 2));
  }
  update.debris_pieces.push_back(static_cast<std::uint32_t>(update.piece_materials.size()));
}

// The landscape a log describes, recording its own log from the start (so that the page can
// share it again, bit for bit).
Landscape replayed_world(const log::ParsedLandscapeLog& parsed) {
  Landscape world = log::make_landscape(*parsed.world);
  world.start_log();
  const std::span<const log::LandscapeEdit> edits(parsed.edits);
  for (std::size_t i = 0; i < edits.size();) {
    const std::size_t n = log::step_size(edits.subspan(i));
    try {
      log::apply_step(world, edits.subspan(i, n));
    } catch (const Error&) {
      break;  // as `edgeland replay` does: the world after the edits before the bad one
    }
    i += n;
  }
  return world;
}

// A game update as the page's arrays.
WebUpdate to_update(const GameUpdate& u) {
  WebUpdate update;
  for (const PolygonId id : u.changes.removed) update.removed.push_back(static_cast<double>(id));
  for (const ChangeSet::Added& a : u.changes.added)
    add_polygon(update, a.id, a.material, a.polygon);
  for (const Box64& cell : u.changes.cells) add_box(update.cells, cell);
  for (const ChainId id : u.chains.removed)
    update.chains_removed.push_back(static_cast<double>(id));
  for (const auto& [id, chain] : u.chains.added) add_chain(update, id, chain);
  for (const Debris& d : u.debris) add_debris(update, d);
  return update;
}

}  // namespace

WebWorld::WebWorld(const Box64& box, Material fill, std::uint64_t seed)
    : session_(starting_world(box, fill, seed), game_options()) {
  session_.settle();  // the islands the world starts with fall; the page starts from everything()
}

WebUpdate WebWorld::apply(const ToolEdit& edit) {
  const auto start = std::chrono::steady_clock::now();
  WebUpdate update;
  try {
    const GameUpdate u = session_.apply(edit);
    update = to_update(u);
    islands_detached_ += u.debris.size();
    ++edits_;
  } catch (const Error& error) {
    update.error = error.what();
  }
  last_edit_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  total_edit_ms_ += last_edit_ms_;
  return update;
}

// The islands the swapped world holds (an undo brings back the ones that were detached) fell
// again with the driver's update; the page redraws everything and adds their debris.
WebUpdate WebWorld::world_swapped(const GameUpdate& u) {
  WebUpdate update = everything();
  for (const Debris& d : u.debris) add_debris(update, d);
  islands_detached_ += u.debris.size();
  return update;
}

WebUpdate WebWorld::undo() {
  const std::optional<GameUpdate> u = session_.undo();
  return u ? world_swapped(*u) : WebUpdate{};
}

WebUpdate WebWorld::redo() {
  const std::optional<GameUpdate> u = session_.redo();
  return u ? world_swapped(*u) : WebUpdate{};
}

WebUpdate WebWorld::everything() const {
  WebUpdate update;
  update.reset = true;
  const Landscape& world = session_.world();
  world.polygons_in(world.world(), [&](const PolygonView& v) {
    add_polygon(update, v.id, v.material, *v.polygon);
    return true;
  });
  for (const auto& [id, chain] : session_.game().chains()) add_chain(update, id, chain);
  return update;
}

WebUpdate WebWorld::load_log(std::string_view text) {
  const log::ParsedLandscapeLog parsed = log::parse_landscape_log(text);
  if (!parsed.world) return WebUpdate{.error = parsed.error->what()};
  const GameUpdate u = session_.reset(replayed_world(parsed));
  edits_ = 0;
  return world_swapped(u);
}

std::vector<std::int32_t> WebWorld::cells() const {
  std::vector<std::int32_t> out;
  const Landscape& world = session_.world();
  world.cells_in(world.world(), [&](const CellView& c) {
    add_box(out, c.box);
    return true;
  });
  return out;
}

std::string WebWorld::state_hash() const {
  return log::state_hash_hex(session_.world().state_hash());
}

WebStats WebWorld::stats() const {
  const LandscapeStats s = session_.world().stats();
  return {s.polygons,        s.vertices,    s.cells,
          s.depth,           edits_,        session_.game().chains().size(),
          islands_detached_, last_edit_ms_, total_edit_ms_};
}

}  // namespace edgeland::play
