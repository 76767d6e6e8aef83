// el_landscape_*: the C++ Landscape's members, one translation each.
#include "edgeland/spatial/landscape.hpp"

#include <cstring>
#include <memory>
#include <new>
#include <sstream>
#include <streambuf>
#include <string>
#include <utility>
#include <vector>

#include "border.hpp"
#include "edgeland/edgeland.h"
#include "handles.hpp"
#include "translate.hpp"

namespace edgeland::capi {
namespace {

el_landscape_config default_config() {
  const LandscapeConfig c;
  const LandscapeLimits l;
  el_landscape_config out{};
  out.struct_size = sizeof(el_landscape_config);
  out.tree = static_cast<std::uint32_t>(c.tree);
  out.edge_cap = c.edge_cap;
  out.merge_below = c.merge_below;
  out.min_cell_size = c.min_cell_size;
  out.grid_depth = c.grid_depth;
  out.max_vertices = l.max_vertices;
  out.max_shape_vertices = l.max_shape_vertices;
  out.max_cells = l.max_cells;
  return out;
}

el_landscape_config config_of(const el_landscape_config* given) {
  return given == nullptr ? default_config() : read_sized(*given, default_config());
}

LandscapeConfig landscape_config(const el_landscape_config& c) {
  LandscapeConfig out;
  // A number that names no tree reaches the C++ check, which refuses it (Setting::kTree).
  out.tree = static_cast<TreeKind>(c.tree > 255 ? 255 : c.tree);
  out.edge_cap = c.edge_cap;
  out.merge_below = c.merge_below;
  out.min_cell_size = c.min_cell_size;
  out.grid_depth = c.grid_depth;
  return out;
}

LandscapeLimits landscape_limits(const el_landscape_config& c) {
  LandscapeLimits out;
  out.max_vertices = static_cast<std::size_t>(c.max_vertices);
  out.max_shape_vertices = static_cast<std::size_t>(c.max_shape_vertices);
  out.max_cells = static_cast<std::size_t>(c.max_cells);
  return out;
}

// One edit with the strong guarantee kept across the border: the edit runs on a snapshot (O(1))
// and its change set is translated before the snapshot replaces the world, so running out of
// memory in the translation leaves the world as it was too.
template <class Edit>
void edit(el_landscape* landscape, el_changes** changes, Edit&& apply) {
  Landscape& world = object_of(landscape, "landscape").world;
  Landscape next = world;
  ChangeSet done = apply(next);
  std::unique_ptr<ChangesHandle> out = changes != nullptr ? to_c(std::move(done)) : nullptr;
  world = std::move(next);
  if (changes != nullptr) hand_out(std::move(out), changes);
}

const ValidSet& shape_of(const el_shape* shape) { return object_of(shape, "shape").set; }

// A read-only stream over the caller's bytes (load reads them once, without a copy).
class BytesIn : public std::streambuf {
 public:
  BytesIn(const std::uint8_t* data, std::size_t size) {
    char* begin = const_cast<char*>(reinterpret_cast<const char*>(data));
    setg(begin, begin, begin + size);
  }
};

// The materials list of overlaps() into the caller's 256 bytes.
void materials_out(const std::vector<Material>& found, std::uint8_t* materials,
                   std::size_t* count) {
  need(materials, "materials");
  need(count, "count");
  for (std::size_t i = 0; i < found.size(); ++i) materials[i] = found[i].value();
  *count = found.size();
}

}  // namespace
}  // namespace edgeland::capi

using namespace edgeland;
using namespace edgeland::capi;

extern "C" {

EL_API void el_landscape_config_init(el_landscape_config* config) {
  if (config != nullptr) *config = default_config();
}

EL_API el_status el_landscape_create(const el_box* world, int32_t fill,
                                     const el_landscape_config* config, el_landscape** out,
                                     el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    const el_landscape_config c = config_of(config);
    auto made = std::make_unique<LandscapeHandle>(LandscapeHandle{Landscape(
        box_of(world, "world"), Material(fill), landscape_config(c), landscape_limits(c))});
    made->world.set_checked((c.flags & EL_LANDSCAPE_CHECKED) != 0);
    hand_out(std::move(made), out);
  });
}

EL_API el_status el_landscape_clone(const el_landscape* landscape, el_landscape** out,
                                    el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    hand_out(
        std::make_unique<LandscapeHandle>(LandscapeHandle{object_of(landscape, "landscape").world}),
        out);
  });
}

EL_API void el_landscape_destroy(el_landscape* landscape) { delete object(landscape); }

EL_API el_status el_landscape_carve(el_landscape* landscape, const el_shape* shape,
                                    el_changes** changes, el_error* error) {
  return execute(error, [&] {
    edit(landscape, changes, [&](Landscape& world) { return world.carve(shape_of(shape)); });
  });
}

EL_API el_status el_landscape_fill(el_landscape* landscape, const el_shape* shape, int32_t material,
                                   el_changes** changes, el_error* error) {
  return execute(error, [&] {
    edit(landscape, changes,
         [&](Landscape& world) { return world.fill(shape_of(shape), Material(material)); });
  });
}

EL_API el_status el_landscape_fill_empty(el_landscape* landscape, const el_shape* shape,
                                         int32_t material, el_changes** changes, el_error* error) {
  return execute(error, [&] {
    edit(landscape, changes,
         [&](Landscape& world) { return world.fill_empty(shape_of(shape), Material(material)); });
  });
}

EL_API el_status el_landscape_replace(el_landscape* landscape, const el_shape* shape, int32_t from,
                                      int32_t to, el_changes** changes, el_error* error) {
  return execute(error, [&] {
    edit(landscape, changes, [&](Landscape& world) {
      return world.replace(shape_of(shape), Material(from), Material(to));
    });
  });
}

EL_API el_status el_landscape_relabel(el_landscape* landscape, const el_shape* shape,
                                      const int32_t* from_to, size_t pair_count,
                                      el_changes** changes, el_error* error) {
  return execute(error, [&] {
    const MaterialMap map = material_map_of(from_to, pair_count);
    edit(landscape, changes, [&](Landscape& world) { return world.relabel(shape_of(shape), map); });
  });
}

EL_API el_status el_landscape_material_at(const el_landscape* landscape, const el_point* p,
                                          uint8_t* material, el_error* error) {
  return execute(error, [&] {
    const Material m = object_of(landscape, "landscape").world.material_at(point_of(p, "p"));
    need(material, "material") = m.value();
  });
}

EL_API el_status el_landscape_crossings(const el_landscape* landscape, const el_point* from,
                                        const el_point* to, el_crossings** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    auto made = std::make_unique<CrossingsHandle>();
    for (const MaterialCrossing& c :
         object_of(landscape, "landscape")
             .world.crossings(point_of(from, "from"), point_of(to, "to"))) {
      made->data.push_back(to_c(c));
    }
    hand_out(std::move(made), out);
  });
}

EL_API el_status el_landscape_raycast(const el_landscape* landscape, const el_point* from,
                                      const el_point* to, int32_t* hit, el_crossing* crossing,
                                      el_error* error) {
  return execute(error, [&] {
    need(hit, "hit");
    need(crossing, "crossing");
    const auto found =
        object_of(landscape, "landscape").world.raycast(point_of(from, "from"), point_of(to, "to"));
    *hit = found.has_value() ? 1 : 0;
    if (found) *crossing = to_c(*found);
  });
}

EL_API el_status el_landscape_overlaps_box(const el_landscape* landscape, const el_box* box,
                                           uint8_t materials[256], size_t* count, el_error* error) {
  return execute(error, [&] {
    materials_out(object_of(landscape, "landscape").world.overlaps(box_of(box, "box")), materials,
                  count);
  });
}

EL_API el_status el_landscape_overlaps_shape(const el_landscape* landscape, const el_shape* shape,
                                             uint8_t materials[256], size_t* count,
                                             el_error* error) {
  return execute(error, [&] {
    materials_out(object_of(landscape, "landscape").world.overlaps(shape_of(shape)), materials,
                  count);
  });
}

EL_API el_status el_landscape_polygons_in(const el_landscape* landscape, const el_box* box,
                                          el_polygons** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    auto made = std::make_unique<PolygonsHandle>();
    object_of(landscape, "landscape")
        .world.polygons_in(box_of(box, "box"), [&](const PolygonView& v) {
          append(*made, v.id, v.material, v.cell, *v.polygon);
          return true;
        });
    hand_out(std::move(made), out);
  });
}

EL_API el_status el_landscape_cells_in(const el_landscape* landscape, const el_box* box,
                                       el_box* buf, size_t cap, size_t* needed, el_error* error) {
  return execute(error, [&] {
    std::vector<el_box> cells;
    object_of(landscape, "landscape").world.cells_in(box_of(box, "box"), [&](const CellView& c) {
      cells.push_back(to_c(c.box));
      return true;
    });
    copy_out(cells, buf, cap, &need(needed, "needed"));
  });
}

EL_API el_status el_landscape_twice_area(const el_landscape* landscape, int32_t material,
                                         el_int128* out, el_error* error) {
  return execute(error, [&] {
    const Int128 twice = object_of(landscape, "landscape").world.twice_area(Material(material));
    need(out, "out") = to_c(twice);
  });
}

EL_API el_status el_landscape_world(const el_landscape* landscape, el_box* out, el_error* error) {
  return execute(error,
                 [&] { need(out, "out") = to_c(object_of(landscape, "landscape").world.world()); });
}

EL_API void el_stats_init(el_stats* stats) {
  if (stats == nullptr) return;
  *stats = el_stats{};
  stats->struct_size = sizeof(el_stats);
}

EL_API el_status el_landscape_stats(const el_landscape* landscape, el_stats* out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    const LandscapeStats s = object_of(landscape, "landscape").world.stats();
    read_sized(*out, el_stats{});  // the caller's struct_size must be one this library knows
    write_sized(out, el_stats{0, 0, s.polygons, s.vertices, s.cells, s.depth, s.bytes});
  });
}

EL_API el_status el_landscape_state_hash(const el_landscape* landscape, uint64_t* out,
                                         el_error* error) {
  return execute(error,
                 [&] { need(out, "out") = object_of(landscape, "landscape").world.state_hash(); });
}

EL_API el_status el_landscape_check(const el_landscape* landscape, el_bytes** problems,
                                    el_error* error) {
  return execute(error, [&] {
    need(problems, "problems");
    std::string text;
    for (const std::string& line : object_of(landscape, "landscape").world.check().problems) {
      text += line + '\n';
    }
    hand_out(bytes_of(std::move(text)), problems);
  });
}

EL_API el_status el_landscape_set_checked(el_landscape* landscape, int32_t on, el_error* error) {
  return execute(error, [&] { object_of(landscape, "landscape").world.set_checked(on != 0); });
}

EL_API el_status el_landscape_start_log(el_landscape* landscape, el_error* error) {
  return execute(error, [&] { object_of(landscape, "landscape").world.start_log(); });
}

EL_API el_status el_landscape_stop_log(el_landscape* landscape, el_error* error) {
  return execute(error, [&] { object_of(landscape, "landscape").world.stop_log(); });
}

EL_API el_status el_landscape_log(const el_landscape* landscape, el_bytes** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    hand_out(bytes_of(object_of(landscape, "landscape").world.log()), out);
  });
}

EL_API el_status el_landscape_save(const el_landscape* landscape, el_bytes** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    std::ostringstream bytes(std::ios::binary);
    object_of(landscape, "landscape").world.save(bytes);
    // A string stream whose buffer cannot grow swallows the std::bad_alloc and sets badbit
    // (iostreams catch what their buffer throws): without this the save would be cut short and
    // handed out as EL_OK.
    if (!bytes) throw std::bad_alloc();
    hand_out(bytes_of(std::move(bytes).str()), out);
  });
}

EL_API el_status el_landscape_load(const uint8_t* data, size_t size,
                                   const el_landscape_config* config, el_landscape** out,
                                   el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    if (size > 0) need(data, "data");
    BytesIn buffer(data, size);
    std::istream in(&buffer);
    const el_landscape_config c = config_of(config);
    hand_out(std::make_unique<LandscapeHandle>(
                 LandscapeHandle{Landscape::load(in, landscape_limits(c))}),
             out);
  });
}

}  // extern "C"
