// The game driver's functions (el_edits_*, el_game_driver_*, el_game_update_*): the C++
// GameDriver (game/include/edgeland/game/game_driver.hpp), one translation each.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "border.hpp"
#include "edgeland/edgeland.h"
#include "edgeland/game/game_driver.hpp"
#include "game_translate.hpp"
#include "handles.hpp"
#include "translate.hpp"

namespace edgeland::capi {
namespace {

std::uint32_t flag(bool on, int bit) { return on ? static_cast<std::uint32_t>(bit) : 0u; }

el_game_options default_options() {
  const GameOptions o;
  el_game_options out{};
  out.struct_size = sizeof(el_game_options);
  out.flags = flag(o.meshes, EL_GAME_MESHES) | flag(o.debris, EL_GAME_DEBRIS) |
              flag(o.surface.border_wall, EL_GAME_BORDER_WALL);
  out.debris_budget = o.debris_budget;
  out.max_piece_vertices = static_cast<std::uint32_t>(o.max_piece_vertices);
  out.max_debris_wait = static_cast<std::uint32_t>(o.max_debris_wait);
  for (std::size_t i = 0; i < kMaterialCount; ++i) {
    out.solid[i] = o.surface.materials.solid[i] ? 1 : 0;
    out.anchored[i] = o.surface.materials.anchored[i] ? 1 : 0;
  }
  return out;
}

GameOptions options_of(const el_game_options* given) {
  const el_game_options c =
      given == nullptr ? default_options() : read_sized(*given, default_options());
  GameOptions out;
  out.meshes = (c.flags & EL_GAME_MESHES) != 0;
  out.debris = (c.flags & EL_GAME_DEBRIS) != 0;
  out.surface.border_wall = (c.flags & EL_GAME_BORDER_WALL) != 0;
  out.debris_budget = static_cast<std::size_t>(c.debris_budget);
  out.max_piece_vertices = c.max_piece_vertices;
  out.max_debris_wait = c.max_debris_wait;
  for (std::size_t i = 0; i < kMaterialCount; ++i) {
    out.surface.materials.solid[i] = c.solid[i] != 0;
    out.surface.materials.anchored[i] = c.anchored[i] != 0;
  }
  return out;
}

el_game_work work_of(const GameUpdate& u) {
  el_game_work out{};
  out.struct_size = sizeof(el_game_work);
  out.cells_scanned = u.work.cells_scanned;
  out.boundary_passes = u.work.boundary_passes;
  out.cells_traced = u.work.cells_traced;
  out.islands_found = u.work.islands_found;
  out.islands_detached = u.work.islands_detached;
  out.debris_waiting = u.debris_waiting;
  return out;
}

void append_debris(GameUpdateHandle& out, const Debris& d) {
  el_debris_info info{};
  info.bounds = to_c(d.bounds);
  info.twice_area = to_c(d.twice_area);
  info.centroid_x_num = to_c(d.centroid.x_num);
  info.centroid_y_num = to_c(d.centroid.y_num);
  info.centroid_den = to_c(d.centroid.den);
  info.first_region = checked_count(out.debris_regions.ids.size());
  for (const Debris::Region& region : d.regions) {
    for (const Polygon& p : region.polygons) append(out.debris_regions, 0, region.material, {}, p);
  }
  info.region_count = checked_count(out.debris_regions.ids.size()) - info.first_region;
  info.first_piece = checked_count(out.debris_pieces.ids.size());
  for (const DebrisPiece& piece : d.pieces)
    append(out.debris_pieces, 0, piece.material, {}, piece.polygon);
  info.piece_count = checked_count(out.debris_pieces.ids.size()) - info.first_piece;
  append_meshes(out.debris_meshes, d.meshes);
  out.debris.push_back(info);
}

// The update's arrays, made before the driver moves on where they can be (the handle itself).
void translate(GameUpdateHandle& out, GameUpdate update) {
  append_chains(out.chains, update.chains);
  out.meshes.dropped = std::move(update.meshes.dropped);
  append_meshes(out.meshes, update.meshes.built);
  for (const Debris& d : update.debris) append_debris(out, d);
  out.work = work_of(update);
  fill(out.changes, std::move(update.changes));
}

std::span<const Edit> edits_of(const el_edits* edits) {
  if (edits == nullptr) return {};
  return object(edits)->edits;
}

// An update handed out to *out, or dropped when the caller did not ask for one.
void hand_out_update(std::unique_ptr<GameUpdateHandle> made, GameUpdate update,
                     el_game_update** out) {
  if (out == nullptr) return;
  translate(*made, std::move(update));
  hand_out(std::move(made), out);
}

template <class Make>
void add_edit(el_edits* edits, const el_shape* shape, Make&& make) {
  std::vector<Edit>& list = object_of(edits, "edits").edits;
  list.push_back(make(ValidSet(object_of(shape, "shape").set)));
}

// An update the driver returned, handed out; if that runs out of memory the caller never gets
// it, and the driver is told so (its next reset() starts from what the caller held before).
void hand_over(GameDriver& driver, std::unique_ptr<GameUpdateHandle> made, GameUpdate u,
               el_game_update** update) {
  try {
    hand_out_update(std::move(made), std::move(u), update);
  } catch (...) {
    driver.update_lost();
    throw;
  }
}

}  // namespace
}  // namespace edgeland::capi

using namespace edgeland;
using namespace edgeland::capi;

extern "C" {

EL_API el_status el_edits_create(el_edits** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    hand_out(std::make_unique<EditsHandle>(), out);
  });
}

EL_API void el_edits_destroy(el_edits* edits) { delete object(edits); }

EL_API void el_edits_clear(el_edits* edits) {
  if (edits != nullptr) object(edits)->edits.clear();
}

EL_API size_t el_edits_count(const el_edits* edits) {
  return edits != nullptr ? object(edits)->edits.size() : 0;
}

EL_API el_status el_edits_carve(el_edits* edits, const el_shape* shape, el_error* error) {
  return execute(
      error, [&] { add_edit(edits, shape, [](ValidSet s) { return Edit::carve(std::move(s)); }); });
}

EL_API el_status el_edits_fill(el_edits* edits, const el_shape* shape, int32_t material,
                               el_error* error) {
  return execute(error, [&] {
    const Material m(material);
    add_edit(edits, shape, [&](ValidSet s) { return Edit::fill(std::move(s), m); });
  });
}

EL_API el_status el_edits_fill_empty(el_edits* edits, const el_shape* shape, int32_t material,
                                     el_error* error) {
  return execute(error, [&] {
    const Material m(material);
    add_edit(edits, shape, [&](ValidSet s) { return Edit::fill_empty(std::move(s), m); });
  });
}

EL_API el_status el_edits_replace(el_edits* edits, const el_shape* shape, int32_t from, int32_t to,
                                  el_error* error) {
  return execute(error, [&] {
    const Material f(from), t(to);
    add_edit(edits, shape, [&](ValidSet s) { return Edit::replace(std::move(s), f, t); });
  });
}

EL_API el_status el_edits_relabel(el_edits* edits, const el_shape* shape, const int32_t* from_to,
                                  size_t pair_count, el_error* error) {
  return execute(error, [&] {
    const MaterialMap map = material_map_of(from_to, pair_count);
    add_edit(edits, shape, [&](ValidSet s) { return Edit::relabel(std::move(s), map); });
  });
}

EL_API void el_game_options_init(el_game_options* options) {
  if (options != nullptr) *options = default_options();
}

EL_API void el_game_work_init(el_game_work* work) {
  if (work != nullptr) *work = el_game_work{sizeof(el_game_work), 0, 0, 0, 0, 0, 0, 0};
}

EL_API el_status el_game_driver_create(const el_landscape* world, const el_game_options* options,
                                       el_game_driver** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    const GameOptions o = options_of(options);
    hand_out(std::make_unique<GameDriverHandle>(
                 GameDriverHandle{GameDriver(object_of(world, "world").world, o)}),
             out);
  });
}

EL_API void el_game_driver_destroy(el_game_driver* driver) { delete object(driver); }

EL_API el_status el_game_driver_apply(el_game_driver* driver, const el_edits* edits,
                                      el_game_update** update, el_error* error) {
  return execute(error, [&] {
    GameDriver& d = object_of(driver, "driver").driver;
    auto made = update != nullptr ? std::make_unique<GameUpdateHandle>() : nullptr;
    hand_over(d, std::move(made), d.apply(edits_of(edits)), update);
  });
}

EL_API el_status el_game_driver_reset(el_game_driver* driver, const el_landscape* world,
                                      el_game_update** update, el_error* error) {
  return execute(error, [&] {
    GameDriver& d = object_of(driver, "driver").driver;
    Landscape next = object_of(world, "world").world;
    auto made = update != nullptr ? std::make_unique<GameUpdateHandle>() : nullptr;
    hand_over(d, std::move(made), d.reset(std::move(next)), update);
  });
}

EL_API el_status el_game_driver_buried(const el_game_driver* driver, const el_box* box,
                                       int32_t* buried, el_error* error) {
  return execute(error, [&] {
    need(buried, "buried");
    *buried = object_of(driver, "driver").driver.buried(box_of(box, "box")) ? 1 : 0;
  });
}

EL_API el_status el_game_driver_landscape(const el_game_driver* driver, el_landscape** out,
                                          el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    hand_out(std::make_unique<LandscapeHandle>(
                 LandscapeHandle{object_of(driver, "driver").driver.landscape()}),
             out);
  });
}

EL_API el_status el_game_driver_chains(const el_game_driver* driver, el_chains** all,
                                       el_error* error) {
  return execute(error, [&] {
    need(all, "all");
    auto made = std::make_unique<ChainsHandle>();
    for (const auto& [id, chain] : object_of(driver, "driver").driver.chains())
      append(*made, id, chain);
    hand_out(std::move(made), all);
  });
}

EL_API size_t el_game_driver_debris_waiting(const el_game_driver* driver) {
  return driver != nullptr ? object(driver)->driver.debris_waiting() : 0;
}

EL_API void el_game_update_destroy(el_game_update* update) { delete object(update); }

EL_API const el_changes* el_game_update_changes(const el_game_update* update) {
  return update != nullptr ? handle<const el_changes>(&object(update)->changes) : nullptr;
}

EL_API const el_chains* el_game_update_chains(const el_game_update* update) {
  return update != nullptr ? handle<const el_chains>(&object(update)->chains) : nullptr;
}

EL_API const el_meshes* el_game_update_meshes(const el_game_update* update) {
  return update != nullptr ? handle<const el_meshes>(&object(update)->meshes) : nullptr;
}

EL_API const el_polygons* el_game_update_debris_regions(const el_game_update* update) {
  return update != nullptr ? handle<const el_polygons>(&object(update)->debris_regions) : nullptr;
}

EL_API const el_meshes* el_game_update_debris_meshes(const el_game_update* update) {
  return update != nullptr ? handle<const el_meshes>(&object(update)->debris_meshes) : nullptr;
}

EL_API const el_polygons* el_game_update_debris_pieces(const el_game_update* update) {
  return update != nullptr ? handle<const el_polygons>(&object(update)->debris_pieces) : nullptr;
}

EL_API el_status el_game_update_work(const el_game_update* update, el_game_work* out,
                                     el_error* error) {
  return execute(error, [&] { write_sized(&need(out, "out"), object_of(update, "update").work); });
}

}  // extern "C"
