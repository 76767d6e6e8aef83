#include "web_world.hpp"

#include <algorithm>
#include <chrono>

#include "edgeland/demo/landscape.hpp"
#include "edgeland/io/landscape_log.hpp"
#include "edgeland/io/landscape_replay.hpp"
#include "edgeland/kernel/convex_pieces.hpp"

namespace edgeland::play {
namespace {

using demo::kWater;

// Water is no obstacle; the world's border is a wall, so that nothing rolls out of the world.
SurfaceOptions surface_options() {
  SurfaceOptions options;
  options.materials.set_solid(kWater, false);
  options.border_wall = true;
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

// A detached island as convex pieces around its exact centroid (at most 8 vertices each: what
// a Box2D or planck.js polygon shape takes).
void add_debris(WebUpdate& update, const DetachedIsland& island) {
  const double cx =
      static_cast<double>(island.centroid.x_num) / static_cast<double>(island.centroid.den);
  const double cy =
      static_cast<double>(island.centroid.y_num) / static_cast<double>(island.centroid.den);
  update.debris_centroids.insert(update.debris_centroids.end(), {cx, cy});
  for (const DetachedIsland::Region& region : island.regions) {
    for (const Polygon& polygon : region.polygons) {
      for (const Polygon& piece : convex_pieces(polygon)) {
        update.piece_materials.push_back(region.material.value());
        for (const Point64& p : piece) {
          update.piece_xy.push_back(static_cast<double>(p.x) - cx);
          update.piece_xy.push_back(static_cast<double>(p.y) - cy);
        }
        update.piece_offsets.push_back(static_cast<std::uint32_t>(update.piece_xy.size() / 2));
      }
    }
  }
  update.debris_pieces.push_back(static_cast<std::uint32_t>(update.piece_materials.size()));
}

// The landscape a log describes, recording its own log from the start (so that the page can
// share it again, bit for bit).
Landscape replayed_world(const log::ParsedLandscapeLog& parsed) {
  Landscape world = log::make_landscape(*parsed.world);
  world.start_log();
  for (const log::LandscapeEdit& edit : parsed.edits) {
    try {
      log::apply_edit(world, edit);
    } catch (const Error&) {
      break;  // as `edgeland replay` does: the world after the edits before the bad one
    }
  }
  return world;
}

WebUpdate to_update(const PendingChanges& p) {
  WebUpdate update;
  for (const PolygonId id : p.removed) update.removed.push_back(static_cast<double>(id));
  for (const auto& [id, polygon] : p.added) add_polygon(update, id, polygon.first, polygon.second);
  for (const Box64& cell : p.cells) add_box(update.cells, cell);
  for (const ChainId id : p.chains_removed)
    update.chains_removed.push_back(static_cast<double>(id));
  for (const auto& [id, chain] : p.chains_added) add_chain(update, id, chain);
  for (const DetachedIsland& island : p.debris) add_debris(update, island);
  return update;
}

}  // namespace

void PendingChanges::take(const ChangeSet& changes) {
  for (const PolygonId id : changes.removed) {
    if (added.erase(id) == 0) removed.push_back(id);
  }
  for (const ChangeSet::Added& a : changes.added) added[a.id] = {a.material, a.polygon};
  cells.insert(cells.end(), changes.cells.begin(), changes.cells.end());
}

void PendingChanges::take(const ChainUpdate& chains) {
  for (const ChainId id : chains.removed) {
    if (chains_added.erase(id) == 0) chains_removed.push_back(id);
  }
  for (const auto& [id, chain] : chains.added) chains_added[id] = chain;
}

WebWorld::WebWorld(const Box64& box, Material fill, std::uint64_t seed)
    : session_(starting_world(box, fill, seed)),
      surface_(session_.world(), surface_options()),
      islands_(session_.world(), surface_options().materials) {
  PendingChanges ignored;  // the page starts from everything()
  settle(islands_.islands(session_.world()), ignored);
}

// Every island falls: detached from the landscape as one edit (given to both trackers), it
// becomes debris. Detaching one island can re-cut the cells of another, which is then stale and
// comes back re-cut from the tracker (game/islands.hpp).
void WebWorld::settle(std::vector<Island> pending, PendingChanges& changes) {
  Landscape& world = session_.world();
  while (!pending.empty()) {
    const Island island = std::move(pending.back());
    pending.pop_back();
    DetachedIsland detached;
    try {
      detached = detach(world, island);
    } catch (const StaleIsland&) {
      continue;  // re-cut by another detach: the tracker reports it again
    } catch (const Error&) {
      continue;  // refused (a bug of the game layer): it stays in the landscape, counted as left
    }
    changes.take(detached.changes);
    changes.take(surface_.update(world, detached.changes));
    for (Island& again : islands_.update(world, detached.changes)) {
      pending.push_back(std::move(again));
    }
    changes.debris.push_back(std::move(detached));
    ++islands_detached_;
  }
}

WebUpdate WebWorld::apply(const ToolEdit& edit) {
  const auto start = std::chrono::steady_clock::now();
  WebUpdate update;
  try {
    const ChangeSet changes = session_.apply(edit);
    const Landscape& world = session_.world();
    PendingChanges pending;
    pending.take(changes);
    pending.take(surface_.update(world, changes));
    settle(islands_.update(world, changes), pending);
    update = to_update(pending);
    ++edits_;
  } catch (const Error& error) {
    update.error = error.what();
  }
  last_edit_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  total_edit_ms_ += last_edit_ms_;
  return update;
}

// The trackers see the whole world again; islands it holds (an undo brings back the ones that
// were detached) are detached again, and the page redraws everything.
WebUpdate WebWorld::world_swapped() {
  surface_.resync(session_.world());
  PendingChanges pending;
  settle(islands_.resync(session_.world()), pending);
  WebUpdate update = everything();
  for (const DetachedIsland& island : pending.debris) add_debris(update, island);
  return update;
}

WebUpdate WebWorld::undo() { return session_.undo() ? world_swapped() : WebUpdate{}; }

WebUpdate WebWorld::redo() { return session_.redo() ? world_swapped() : WebUpdate{}; }

WebUpdate WebWorld::everything() const {
  WebUpdate update;
  update.reset = true;
  const Landscape& world = session_.world();
  world.polygons_in(world.world(), [&](const PolygonView& v) {
    add_polygon(update, v.id, v.material, *v.polygon);
    return true;
  });
  for (const auto& [id, chain] : surface_.chains()) add_chain(update, id, chain);
  return update;
}

WebUpdate WebWorld::load_log(std::string_view text) {
  const log::ParsedLandscapeLog parsed = log::parse_landscape_log(text);
  if (!parsed.world) return WebUpdate{.error = parsed.error->what()};
  session_.reset(replayed_world(parsed));
  edits_ = 0;
  return world_swapped();
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
          s.depth,           edits_,        surface_.chains().size(),
          islands_detached_, last_edit_ms_, total_edit_ms_};
}

}  // namespace edgeland::play
