#include "web_world.hpp"

#include <chrono>

#include "landscape_log.hpp"
#include "landscape_report.hpp"

namespace edgeland::play {
namespace {

Landscape starting_world(const Box64& box, Material fill, std::uint64_t seed) {
  if (seed > 0) return demo_landscape(box, seed);
  Landscape world(box, fill);
  world.start_log();
  return world;
}

void add_polygon(WebUpdate& update, PolygonId id, Material material, const Polygon& polygon) {
  update.ids.push_back(static_cast<double>(id));
  update.materials.push_back(material);
  for (const Point64& p : polygon) {
    update.xy.push_back(static_cast<std::int32_t>(p.x));
    update.xy.push_back(static_cast<std::int32_t>(p.y));
  }
  update.offsets.push_back(static_cast<std::uint32_t>(update.xy.size() / 2));
}

void add_box(std::vector<std::int32_t>& out, const Box64& b) {
  for (const std::int64_t c : {b.min.x, b.min.y, b.max.x, b.max.y}) {
    out.push_back(static_cast<std::int32_t>(c));
  }
}

WebUpdate from_changes(const ChangeSet& changes) {
  WebUpdate update;
  for (const Box64& cell : changes.cells) add_box(update.cells, cell);
  for (const PolygonId id : changes.removed) update.removed.push_back(static_cast<double>(id));
  for (const ChangeSet::Added& a : changes.added) add_polygon(update, a.id, a.material, a.polygon);
  return update;
}

// The landscape a log describes, recording its own log so that the page can share it again.
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

}  // namespace

WebWorld::WebWorld(const Box64& box, Material fill, std::uint64_t seed)
    : session_(starting_world(box, fill, seed)) {}

WebUpdate WebWorld::apply(const ToolEdit& edit) {
  const auto start = std::chrono::steady_clock::now();
  WebUpdate update;
  try {
    if (const std::optional<ChangeSet> changes = session_.apply(edit)) {
      update = from_changes(*changes);
      ++edits_;
    }
  } catch (const Error& error) {
    update.error = error.what();
  }
  last_edit_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  total_edit_ms_ += last_edit_ms_;
  return update;
}

WebUpdate WebWorld::undo() { return session_.undo() ? everything() : WebUpdate{}; }

WebUpdate WebWorld::redo() { return session_.redo() ? everything() : WebUpdate{}; }

WebUpdate WebWorld::everything() const {
  WebUpdate update;
  update.reset = true;
  const Landscape& world = session_.world();
  world.polygons_in(world.world(), [&](const PolygonView& v) {
    add_polygon(update, v.id, v.material, *v.polygon);
    return true;
  });
  return update;
}

WebUpdate WebWorld::load_log(std::string_view text) {
  const log::ParsedLandscapeLog parsed = log::parse_landscape_log(text);
  if (!parsed.world) return WebUpdate{.error = parsed.error->what()};
  session_.reset(replayed_world(parsed));
  edits_ = 0;
  return everything();
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
  return cli::state_hash_hex(session_.world().state_hash());
}

WebStats WebWorld::stats() const {
  const LandscapeStats s = session_.world().stats();
  return {s.polygons, s.vertices, s.cells, s.depth, edits_, last_edit_ms_, total_edit_ms_};
}

}  // namespace edgeland::play
