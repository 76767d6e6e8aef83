// el_shape_*: a validated polygon set, from CSR arrays or kernel/shapes.hpp's builders.
#include "edgeland/kernel/shapes.hpp"

#include <memory>

#include "border.hpp"
#include "edgeland/edgeland.h"
#include "handles.hpp"
#include "translate.hpp"

namespace edgeland::capi {
namespace {

// A builder's polygon as a shape: valid by construction, and checked once more as a ValidSet
// like every shape an edit is given.
template <class Build>
el_status built(el_shape** out, el_error* error, Build&& build) {
  return execute(error, [&] {
    need(out, "out");
    hand_out(
        std::make_unique<ShapeHandle>(ShapeHandle{ValidSet(PolygonSet{build()}, Operand::kClip)}),
        out);
  });
}

}  // namespace
}  // namespace edgeland::capi

using namespace edgeland;
using namespace edgeland::capi;

extern "C" {

EL_API el_status el_shape_create(const int64_t* xy, const uint32_t* offsets, size_t polygon_count,
                                 el_shape** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    PolygonSet set = polygon_set_of(xy, offsets, polygon_count);
    hand_out(std::make_unique<ShapeHandle>(ShapeHandle{ValidSet(std::move(set), Operand::kClip)}),
             out);
  });
}

EL_API el_status el_shape_circle(const el_point* center, int64_t radius, el_shape** out,
                                 el_error* error) {
  return built(out, error, [&] { return circle(point_of(center, "center"), radius); });
}

EL_API el_status el_shape_regular_polygon(const el_point* center, int64_t radius, int64_t sides,
                                          int64_t phase_num, int64_t phase_den, el_shape** out,
                                          el_error* error) {
  return built(out, error, [&] {
    return regular_polygon(point_of(center, "center"), radius, sides, Turn{phase_num, phase_den});
  });
}

EL_API el_status el_shape_capsule(const el_point* a, const el_point* b, int64_t radius,
                                  el_shape** out, el_error* error) {
  return built(out, error, [&] { return capsule(point_of(a, "a"), point_of(b, "b"), radius); });
}

EL_API el_status el_shape_box(const el_box* box, el_shape** out, el_error* error) {
  return built(out, error, [&] { return box_shape(box_of(box, "box")); });
}

EL_API el_status el_shape_rotated_box(const el_point* center, int64_t half_width,
                                      int64_t half_height, int64_t angle_num, int64_t angle_den,
                                      el_shape** out, el_error* error) {
  return built(out, error, [&] {
    return rotated_box(point_of(center, "center"), half_width, half_height,
                       Turn{angle_num, angle_den});
  });
}

EL_API el_status el_shape_polygons(const el_shape* shape, el_polygons** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    auto made = std::make_unique<PolygonsHandle>();
    for (const Polygon& p : object_of(shape, "shape").set.polygons())
      append(*made, 0, kEmpty, {}, p);
    hand_out(std::move(made), out);
  });
}

EL_API void el_shape_destroy(el_shape* shape) { delete object(shape); }

}  // extern "C"
