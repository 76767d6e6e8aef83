#pragma once
// What the handles of edgeland.h are: each a C++ value, or the C arrays translated from one.
// Private to capi/src. The C types (el_landscape, ...) stay incomplete everywhere, in the header
// and here: a handle pointer is one of these objects cast, so the library's debug info, and with
// it the ABI baseline (capi/abi), shows an opaque pointer and nothing of the C++ inside.
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "edgeland/clip/valid_set.hpp"
#include "edgeland/edgeland.h"
#include "edgeland/game/game_driver.hpp"
#include "edgeland/game/islands.hpp"
#include "edgeland/game/surface_tracker.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::capi {

struct LandscapeHandle {
  Landscape world;
};

struct ShapeHandle {
  ValidSet set;
};

// Polygons as parallel arrays (offsets has one entry more than the polygons). A borrowed one is
// a member of another handle, and el_polygons_destroy leaves it alone.
struct PolygonsHandle {
  bool borrowed = false;
  std::vector<std::uint64_t> ids;
  std::vector<std::uint8_t> materials;
  std::vector<el_box> cells;
  std::vector<std::uint32_t> offsets{0};
  std::vector<el_point> points;
};

// A result handle that lives inside another (el_*_destroy leaves it alone).
template <class Handle>
Handle borrowed() {
  Handle h;
  h.borrowed = true;
  return h;
}

inline PolygonsHandle borrowed_polygons() { return borrowed<PolygonsHandle>(); }

// A change set: the C++ value (the trackers and mesh_update take it) and its arrays.
struct ChangesHandle {
  bool borrowed = false;
  ChangeSet source;
  std::vector<std::uint64_t> removed;
  PolygonsHandle added = borrowed_polygons();
  std::vector<el_box> cells;
  std::vector<el_area_delta> area_delta;
};

struct SurfaceTrackerHandle {
  SurfaceTracker tracker;
};

struct IslandTrackerHandle {
  IslandTracker tracker;
};

// Chains as arrays (offsets has one entry more than the chains), and the ids an update removed.
// A borrowed one is a member of another handle (el_game_update), as for polygons.
struct ChainsHandle {
  bool borrowed = false;
  std::vector<std::uint64_t> removed;
  std::vector<el_chain_info> info;
  std::vector<std::uint32_t> offsets{0};
  std::vector<el_point> points;
  std::vector<std::uint8_t> materials;
};

// Islands: the C++ values (detach takes one) and their arrays.
struct IslandsHandle {
  std::vector<Island> islands;
  std::vector<el_island_info> info;
  PolygonsHandle pieces = borrowed_polygons();
};

struct DetachedHandle {
  el_detached_info summary{};
  ChangesHandle changes;  // borrowed
  PolygonsHandle regions = borrowed_polygons();
};

struct MeshesHandle {
  bool borrowed = false;
  std::vector<std::uint64_t> dropped;
  PolygonsHandle polygons = borrowed_polygons();
  std::vector<std::uint32_t> triangle_offsets{0};
  std::vector<std::uint32_t> triangles;
};

// A frame's edits, each with its own copy of the shape (el_edits).
struct EditsHandle {
  std::vector<Edit> edits;
};

struct GameDriverHandle {
  GameDriver driver;
};

// An update's arrays, all borrowed by the caller through el_game_update_*; the debris bodies'
// regions, pieces and meshes in one array each, every body's a run of them (el_debris_info).
struct GameUpdateHandle {
  ChangesHandle changes = borrowed<ChangesHandle>();
  ChainsHandle chains = borrowed<ChainsHandle>();
  MeshesHandle meshes = borrowed<MeshesHandle>();
  std::vector<el_debris_info> debris;
  PolygonsHandle debris_regions = borrowed_polygons();
  PolygonsHandle debris_pieces = borrowed_polygons();
  MeshesHandle debris_meshes = borrowed<MeshesHandle>();
  el_game_work work{};
};

struct CrossingsHandle {
  std::vector<el_crossing> data;
};

struct BytesHandle {
  std::string data;
};

// Which C++ object each C handle type stands for.
template <class C>
struct HandleOf;
template <>
struct HandleOf<el_landscape> {
  using type = LandscapeHandle;
};
template <>
struct HandleOf<el_shape> {
  using type = ShapeHandle;
};
template <>
struct HandleOf<el_polygons> {
  using type = PolygonsHandle;
};
template <>
struct HandleOf<el_changes> {
  using type = ChangesHandle;
};
template <>
struct HandleOf<el_crossings> {
  using type = CrossingsHandle;
};
template <>
struct HandleOf<el_bytes> {
  using type = BytesHandle;
};

template <>
struct HandleOf<el_surface_tracker> {
  using type = SurfaceTrackerHandle;
};

template <>
struct HandleOf<el_island_tracker> {
  using type = IslandTrackerHandle;
};

template <>
struct HandleOf<el_chains> {
  using type = ChainsHandle;
};

template <>
struct HandleOf<el_islands> {
  using type = IslandsHandle;
};

template <>
struct HandleOf<el_detached> {
  using type = DetachedHandle;
};

template <>
struct HandleOf<el_meshes> {
  using type = MeshesHandle;
};

template <>
struct HandleOf<el_edits> {
  using type = EditsHandle;
};

template <>
struct HandleOf<el_game_driver> {
  using type = GameDriverHandle;
};

template <>
struct HandleOf<el_game_update> {
  using type = GameUpdateHandle;
};

// The object behind a handle (NULL stays NULL), const as the handle is.
template <class C>
auto* object(C* handle) noexcept {
  using T = typename HandleOf<std::remove_const_t<C>>::type;
  using Out = std::conditional_t<std::is_const_v<C>, const T, T>;
  return reinterpret_cast<Out*>(handle);
}

// The handle of an object.
template <class C, class T>
C* handle(T* object) noexcept {
  return reinterpret_cast<C*>(object);
}

}  // namespace edgeland::capi
