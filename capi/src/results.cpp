// The result handles' arrays: a pointer valid until the handle is destroyed, or a copy into the
// caller's buffer.
#include <algorithm>
#include <string>
#include <vector>

#include "border.hpp"
#include "edgeland/edgeland.h"
#include "handles.hpp"

namespace edgeland::capi {
namespace {

// The array behind a handle (none for a NULL handle), as pointer and count.
template <class C, class Object, class T>
const T* view(const C* h, const std::vector<T> Object::*field, size_t* count) noexcept {
  const std::vector<T>* v = h != nullptr ? &(object(h)->*field) : nullptr;
  if (count != nullptr) *count = v != nullptr ? v->size() : 0;
  return v != nullptr && !v->empty() ? v->data() : nullptr;
}

template <class T>
void copy_out(const std::vector<T>& v, T* buf, size_t cap, size_t* needed) {
  if (needed != nullptr) *needed = v.size();
  if (cap < v.size()) {
    throw BorderError(EL_BUFFER_TOO_SMALL, "buffer of " + std::to_string(cap) + " for " +
                                               std::to_string(v.size()) + " elements");
  }
  if (!v.empty()) std::copy(v.begin(), v.end(), &need(buf, "buf"));
}

template <class C, class Object, class T>
el_status copy(const C* h, const std::vector<T> Object::*field, T* buf, size_t cap,
               size_t* needed) noexcept {
  return execute(nullptr, [&] { copy_out(need(object(h), "handle").*field, buf, cap, needed); });
}

}  // namespace
}  // namespace edgeland::capi

using namespace edgeland::capi;

extern "C" {

EL_API void el_changes_destroy(el_changes* changes) {
  if (changes != nullptr && !object(changes)->borrowed) delete object(changes);
}
EL_API const uint64_t* el_changes_removed(const el_changes* h, size_t* count) {
  return view(h, &ChangesHandle::removed, count);
}
EL_API el_status el_changes_copy_removed(const el_changes* h, uint64_t* buf, size_t cap,
                                         size_t* needed) {
  return copy(h, &ChangesHandle::removed, buf, cap, needed);
}
EL_API const el_polygons* el_changes_added(const el_changes* h) {
  return h != nullptr ? handle<const el_polygons>(&object(h)->added) : nullptr;
}
EL_API const el_box* el_changes_cells(const el_changes* h, size_t* count) {
  return view(h, &ChangesHandle::cells, count);
}
EL_API el_status el_changes_copy_cells(const el_changes* h, el_box* buf, size_t cap,
                                       size_t* needed) {
  return copy(h, &ChangesHandle::cells, buf, cap, needed);
}
EL_API const el_area_delta* el_changes_area_delta(const el_changes* h, size_t* count) {
  return view(h, &ChangesHandle::area_delta, count);
}
EL_API el_status el_changes_copy_area_delta(const el_changes* h, el_area_delta* buf, size_t cap,
                                            size_t* needed) {
  return copy(h, &ChangesHandle::area_delta, buf, cap, needed);
}

EL_API void el_polygons_destroy(el_polygons* h) {
  if (h != nullptr && !object(h)->borrowed) delete object(h);
}
EL_API size_t el_polygons_count(const el_polygons* h) {
  return h != nullptr ? object(h)->ids.size() : 0;
}
EL_API const uint64_t* el_polygons_ids(const el_polygons* h, size_t* count) {
  return view(h, &PolygonsHandle::ids, count);
}
EL_API el_status el_polygons_copy_ids(const el_polygons* h, uint64_t* buf, size_t cap,
                                      size_t* needed) {
  return copy(h, &PolygonsHandle::ids, buf, cap, needed);
}
EL_API const uint8_t* el_polygons_materials(const el_polygons* h, size_t* count) {
  return view(h, &PolygonsHandle::materials, count);
}
EL_API el_status el_polygons_copy_materials(const el_polygons* h, uint8_t* buf, size_t cap,
                                            size_t* needed) {
  return copy(h, &PolygonsHandle::materials, buf, cap, needed);
}
EL_API const el_box* el_polygons_cells(const el_polygons* h, size_t* count) {
  return view(h, &PolygonsHandle::cells, count);
}
EL_API el_status el_polygons_copy_cells(const el_polygons* h, el_box* buf, size_t cap,
                                        size_t* needed) {
  return copy(h, &PolygonsHandle::cells, buf, cap, needed);
}
EL_API const uint32_t* el_polygons_offsets(const el_polygons* h, size_t* count) {
  return view(h, &PolygonsHandle::offsets, count);
}
EL_API el_status el_polygons_copy_offsets(const el_polygons* h, uint32_t* buf, size_t cap,
                                          size_t* needed) {
  return copy(h, &PolygonsHandle::offsets, buf, cap, needed);
}
EL_API const el_point* el_polygons_points(const el_polygons* h, size_t* count) {
  return view(h, &PolygonsHandle::points, count);
}
EL_API el_status el_polygons_copy_points(const el_polygons* h, el_point* buf, size_t cap,
                                         size_t* needed) {
  return copy(h, &PolygonsHandle::points, buf, cap, needed);
}

EL_API void el_chains_destroy(el_chains* h) {
  if (h != nullptr && !object(h)->borrowed) delete object(h);
}
EL_API const uint64_t* el_chains_removed(const el_chains* h, size_t* count) {
  return view(h, &ChainsHandle::removed, count);
}
EL_API el_status el_chains_copy_removed(const el_chains* h, uint64_t* buf, size_t cap,
                                        size_t* needed) {
  return copy(h, &ChainsHandle::removed, buf, cap, needed);
}
EL_API const el_chain_info* el_chains_info(const el_chains* h, size_t* count) {
  return view(h, &ChainsHandle::info, count);
}
EL_API el_status el_chains_copy_info(const el_chains* h, el_chain_info* buf, size_t cap,
                                     size_t* needed) {
  return copy(h, &ChainsHandle::info, buf, cap, needed);
}
EL_API const uint32_t* el_chains_offsets(const el_chains* h, size_t* count) {
  return view(h, &ChainsHandle::offsets, count);
}
EL_API el_status el_chains_copy_offsets(const el_chains* h, uint32_t* buf, size_t cap,
                                        size_t* needed) {
  return copy(h, &ChainsHandle::offsets, buf, cap, needed);
}
EL_API const el_point* el_chains_points(const el_chains* h, size_t* count) {
  return view(h, &ChainsHandle::points, count);
}
EL_API el_status el_chains_copy_points(const el_chains* h, el_point* buf, size_t cap,
                                       size_t* needed) {
  return copy(h, &ChainsHandle::points, buf, cap, needed);
}
EL_API const uint8_t* el_chains_materials(const el_chains* h, size_t* count) {
  return view(h, &ChainsHandle::materials, count);
}
EL_API el_status el_chains_copy_materials(const el_chains* h, uint8_t* buf, size_t cap,
                                          size_t* needed) {
  return copy(h, &ChainsHandle::materials, buf, cap, needed);
}

EL_API void el_islands_destroy(el_islands* h) { delete object(h); }
EL_API size_t el_islands_count(const el_islands* h) {
  return h != nullptr ? object(h)->info.size() : 0;
}
EL_API const el_island_info* el_islands_info(const el_islands* h, size_t* count) {
  return view(h, &IslandsHandle::info, count);
}
EL_API el_status el_islands_copy_info(const el_islands* h, el_island_info* buf, size_t cap,
                                      size_t* needed) {
  return copy(h, &IslandsHandle::info, buf, cap, needed);
}
EL_API const el_polygons* el_islands_pieces(const el_islands* h) {
  return h != nullptr ? handle<const el_polygons>(&object(h)->pieces) : nullptr;
}

EL_API const uint64_t* el_meshes_dropped(const el_meshes* h, size_t* count) {
  return view(h, &MeshesHandle::dropped, count);
}
EL_API el_status el_meshes_copy_dropped(const el_meshes* h, uint64_t* buf, size_t cap,
                                        size_t* needed) {
  return copy(h, &MeshesHandle::dropped, buf, cap, needed);
}
EL_API const uint32_t* el_meshes_triangle_offsets(const el_meshes* h, size_t* count) {
  return view(h, &MeshesHandle::triangle_offsets, count);
}
EL_API el_status el_meshes_copy_triangle_offsets(const el_meshes* h, uint32_t* buf, size_t cap,
                                                 size_t* needed) {
  return copy(h, &MeshesHandle::triangle_offsets, buf, cap, needed);
}
EL_API const uint32_t* el_meshes_triangles(const el_meshes* h, size_t* count) {
  return view(h, &MeshesHandle::triangles, count);
}
EL_API el_status el_meshes_copy_triangles(const el_meshes* h, uint32_t* buf, size_t cap,
                                          size_t* needed) {
  return copy(h, &MeshesHandle::triangles, buf, cap, needed);
}

EL_API void el_crossings_destroy(el_crossings* h) { delete object(h); }
EL_API const el_crossing* el_crossings_data(const el_crossings* h, size_t* count) {
  return view(h, &CrossingsHandle::data, count);
}
EL_API el_status el_crossings_copy(const el_crossings* h, el_crossing* buf, size_t cap,
                                   size_t* needed) {
  return copy(h, &CrossingsHandle::data, buf, cap, needed);
}

EL_API void el_bytes_destroy(el_bytes* h) { delete object(h); }
EL_API const uint8_t* el_bytes_data(const el_bytes* h, size_t* size) {
  if (size != nullptr) *size = h != nullptr ? object(h)->data.size() : 0;
  return h != nullptr && !object(h)->data.empty()
             ? reinterpret_cast<const uint8_t*>(object(h)->data.data())
             : nullptr;
}
EL_API el_status el_bytes_copy(const el_bytes* h, uint8_t* buf, size_t cap, size_t* needed) {
  return execute(nullptr, [&] {
    const std::string& data = need(object(h), "bytes").data;
    if (needed != nullptr) *needed = data.size();
    if (cap < data.size()) throw BorderError(EL_BUFFER_TOO_SMALL, "buffer too small");
    if (!data.empty())
      std::copy(data.begin(), data.end(), reinterpret_cast<char*>(&need(buf, "buf")));
  });
}

EL_API const el_debris_info* el_game_update_debris(const el_game_update* h, size_t* count) {
  return view(h, &GameUpdateHandle::debris, count);
}
EL_API el_status el_game_update_copy_debris(const el_game_update* h, el_debris_info* buf,
                                            size_t cap, size_t* needed) {
  return copy(h, &GameUpdateHandle::debris, buf, cap, needed);
}

}  // extern "C"
