// The game layer's functions (game/): trackers, detach, meshes, convex pieces, one translation
// each.
#include <memory>
#include <utility>

#include "border.hpp"
#include "edgeland/edgeland.h"
#include "edgeland/game/islands.hpp"
#include "edgeland/game/render_meshes.hpp"
#include "edgeland/game/surface_tracker.hpp"
#include "edgeland/kernel/convex_pieces.hpp"
#include "game_translate.hpp"
#include "handles.hpp"
#include "translate.hpp"

namespace edgeland::capi {
namespace {

el_physics_materials default_materials() {
  el_physics_materials out{};
  out.struct_size = sizeof(el_physics_materials);
  const PhysicsMaterials m;
  for (std::size_t i = 0; i < kMaterialCount; ++i) {
    out.solid[i] = m.solid[i] ? 1 : 0;
    out.anchored[i] = m.anchored[i] ? 1 : 0;
  }
  return out;
}

SurfaceOptions options_of(const el_physics_materials* given) {
  const el_physics_materials c =
      given == nullptr ? default_materials() : read_sized(*given, default_materials());
  SurfaceOptions out;
  for (std::size_t i = 0; i < kMaterialCount; ++i) {
    out.materials.solid[i] = c.solid[i] != 0;
    out.materials.anchored[i] = c.anchored[i] != 0;
  }
  out.border_wall = (c.flags & EL_SURFACE_BORDER_WALL) != 0;
  return out;
}

std::unique_ptr<ChainsHandle> chains_of(const ChainUpdate& update) {
  auto out = std::make_unique<ChainsHandle>();
  append_chains(*out, update);
  return out;
}

std::unique_ptr<IslandsHandle> islands_of(std::vector<Island> islands) {
  auto out = std::make_unique<IslandsHandle>();
  for (const Island& island : islands) {
    el_island_info info{};
    info.bounds = to_c(island.bounds);
    info.twice_area = to_c(island.twice_area);
    info.first_piece = checked_count(out->pieces.ids.size());
    info.piece_count = checked_count(island.pieces.size());
    out->info.push_back(info);
    for (const IslandPiece& p : island.pieces)
      append(out->pieces, p.id, p.material, p.cell, p.polygon);
  }
  out->islands = std::move(islands);
  return out;
}

std::unique_ptr<MeshesHandle> meshes_of(std::vector<PolygonId> dropped,
                                        const std::vector<PolygonMesh>& built) {
  auto out = std::make_unique<MeshesHandle>();
  out->dropped = std::move(dropped);
  append_meshes(*out, built);
  return out;
}

const ChangeSet& changes_of(const el_changes* changes) {
  return object_of(changes, "changes").source;
}

}  // namespace
}  // namespace edgeland::capi

using namespace edgeland;
using namespace edgeland::capi;

extern "C" {

EL_API void el_physics_materials_init(el_physics_materials* materials) {
  if (materials != nullptr) *materials = default_materials();
}

EL_API el_status el_surface_tracker_create(const el_landscape* landscape,
                                           const el_physics_materials* materials,
                                           el_surface_tracker** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    hand_out(std::make_unique<SurfaceTrackerHandle>(SurfaceTrackerHandle{
                 SurfaceTracker(object_of(landscape, "landscape").world, options_of(materials))}),
             out);
  });
}

EL_API void el_surface_tracker_destroy(el_surface_tracker* tracker) { delete object(tracker); }

EL_API el_status el_surface_tracker_update(el_surface_tracker* tracker,
                                           const el_landscape* landscape, const el_changes* changes,
                                           el_chains** update, el_error* error) {
  return execute(error, [&] {
    need(update, "update");
    SurfaceTracker& t = object_of(tracker, "tracker").tracker;
    hand_out(chains_of(t.update(object_of(landscape, "landscape").world, changes_of(changes))),
             update);
  });
}

EL_API el_status el_surface_tracker_resync(el_surface_tracker* tracker,
                                           const el_landscape* landscape, el_chains** update,
                                           el_error* error) {
  return execute(error, [&] {
    need(update, "update");
    SurfaceTracker& t = object_of(tracker, "tracker").tracker;
    hand_out(chains_of(t.resync(object_of(landscape, "landscape").world)), update);
  });
}

EL_API el_status el_surface_tracker_chains(const el_surface_tracker* tracker, el_chains** all,
                                           el_error* error) {
  return execute(error, [&] {
    need(all, "all");
    auto made = std::make_unique<ChainsHandle>();
    for (const auto& [id, chain] : object_of(tracker, "tracker").tracker.chains()) {
      append(*made, id, chain);
    }
    hand_out(std::move(made), all);
  });
}

EL_API el_status el_island_tracker_create(const el_landscape* landscape,
                                          const el_physics_materials* materials,
                                          el_island_tracker** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    hand_out(std::make_unique<IslandTrackerHandle>(IslandTrackerHandle{IslandTracker(
                 object_of(landscape, "landscape").world, options_of(materials).materials)}),
             out);
  });
}

EL_API void el_island_tracker_destroy(el_island_tracker* tracker) { delete object(tracker); }

EL_API el_status el_island_tracker_update(el_island_tracker* tracker, const el_landscape* landscape,
                                          const el_changes* changes, el_islands** found,
                                          el_error* error) {
  return execute(error, [&] {
    need(found, "found");
    IslandTracker& t = object_of(tracker, "tracker").tracker;
    hand_out(islands_of(t.update(object_of(landscape, "landscape").world, changes_of(changes))),
             found);
  });
}

EL_API el_status el_island_tracker_resync(el_island_tracker* tracker, const el_landscape* landscape,
                                          el_islands** found, el_error* error) {
  return execute(error, [&] {
    need(found, "found");
    IslandTracker& t = object_of(tracker, "tracker").tracker;
    hand_out(islands_of(t.resync(object_of(landscape, "landscape").world)), found);
  });
}

EL_API el_status el_island_tracker_islands(const el_island_tracker* tracker,
                                           const el_landscape* landscape, el_islands** all,
                                           el_error* error) {
  return execute(error, [&] {
    need(all, "all");
    const IslandTracker& t = object_of(tracker, "tracker").tracker;
    hand_out(islands_of(t.islands(object_of(landscape, "landscape").world)), all);
  });
}

EL_API el_status el_detach(el_landscape* landscape, const el_islands* islands, size_t index,
                           el_detached** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    const std::vector<Island>& all = object_of(islands, "islands").islands;
    if (index >= all.size()) {
      throw BorderError(EL_INDEX_OUT_OF_RANGE,
                        "island " + std::to_string(index) + " of " + std::to_string(all.size()));
    }
    // As every edit: on a snapshot, translated, then committed (the strong guarantee).
    Landscape& world = object_of(landscape, "landscape").world;
    Landscape next = world;
    DetachedIsland d = detach(next, all[index]);
    auto made = std::make_unique<DetachedHandle>();
    made->summary = {to_c(d.twice_area), to_c(d.centroid.x_num), to_c(d.centroid.y_num),
                     to_c(d.centroid.den)};
    for (const DetachedIsland::Region& region : d.regions) {
      for (const Polygon& p : region.polygons) append(made->regions, 0, region.material, {}, p);
    }
    made->changes.borrowed = true;
    fill(made->changes, std::move(d.changes));
    world = std::move(next);
    hand_out(std::move(made), out);
  });
}

EL_API void el_detached_destroy(el_detached* detached) { delete object(detached); }

EL_API el_status el_detached_summary(const el_detached* detached, el_detached_info* out,
                                     el_error* error) {
  return execute(error, [&] { need(out, "out") = object_of(detached, "detached").summary; });
}

EL_API const el_changes* el_detached_changes(const el_detached* detached) {
  return detached != nullptr ? handle<const el_changes>(&object(detached)->changes) : nullptr;
}

EL_API const el_polygons* el_detached_regions(const el_detached* detached) {
  return detached != nullptr ? handle<const el_polygons>(&object(detached)->regions) : nullptr;
}

EL_API el_status el_mesh_update(const el_changes* changes, el_meshes** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    MeshUpdate update = mesh_update(changes_of(changes));
    hand_out(meshes_of(std::move(update.dropped), update.built), out);
  });
}

EL_API el_status el_all_meshes(const el_landscape* landscape, el_meshes** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    hand_out(meshes_of({}, all_meshes(object_of(landscape, "landscape").world)), out);
  });
}

EL_API void el_meshes_destroy(el_meshes* meshes) {
  if (meshes != nullptr && !object(meshes)->borrowed) delete object(meshes);
}

EL_API const el_polygons* el_meshes_polygons(const el_meshes* meshes) {
  return meshes != nullptr ? handle<const el_polygons>(&object(meshes)->polygons) : nullptr;
}

EL_API el_status el_convex_pieces(const el_point* points, size_t count, uint32_t max_vertices,
                                  el_polygons** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    if (count > 0) need(points, "points");
    Polygon polygon;
    for (std::size_t i = 0; i < count; ++i) polygon.push_back({points[i].x, points[i].y});
    auto made = std::make_unique<PolygonsHandle>();
    for (const Polygon& piece : convex_pieces(polygon, max_vertices)) {
      append(*made, 0, kEmpty, {}, piece);
    }
    hand_out(std::move(made), out);
  });
}

}  // extern "C"
