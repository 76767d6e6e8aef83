#include "translate.hpp"

#include <limits>
#include <string>

#include "border.hpp"

namespace edgeland::capi {

el_int128 to_c(Int128 v) noexcept {
  const Int128Words w = to_words(v);
  return {w.lo, w.hi, static_cast<double>(v)};
}

el_crossing to_c(const MaterialCrossing& c) noexcept {
  el_crossing out{};
  out.t_num = to_c(c.t.num);
  out.t_den = to_c(c.t.den);
  out.x_num = to_c(c.point.x_num);
  out.y_num = to_c(c.point.y_num);
  out.den = to_c(c.point.den);
  out.rounded = to_c(c.rounded);
  out.normal = to_c(c.normal);
  out.polygon = c.polygon;
  out.edge = c.edge;
  out.before = c.before.value();
  out.after = c.after.value();
  return out;
}

Point64 point_of(const el_point* p, const char* name) {
  const el_point& q = need(p, name);
  return {q.x, q.y};
}

Box64 box_of(const el_box* b, const char* name) {
  const el_box& q = need(b, name);
  return {{q.min.x, q.min.y}, {q.max.x, q.max.y}};
}

PolygonSet polygon_set_of(const std::int64_t* xy, const std::uint32_t* offsets,
                          std::size_t polygon_count) {
  need(offsets, "offsets");
  if (offsets[polygon_count] > 0) need(xy, "xy");
  PolygonSet set(polygon_count);
  for (std::size_t i = 0; i < polygon_count; ++i) {
    if (offsets[i + 1] < offsets[i]) {
      throw BorderError(EL_INVALID_ARGUMENT, "offsets[" + std::to_string(i + 1) +
                                                 "] is below offsets[" + std::to_string(i) + "]");
    }
    for (std::uint32_t k = offsets[i]; k < offsets[i + 1]; ++k) {
      set[i].push_back({xy[2 * std::size_t{k}], xy[2 * std::size_t{k} + 1]});
    }
  }
  return set;
}

MaterialMap material_map_of(const std::int32_t* from_to, std::size_t pair_count) {
  MaterialMap map;
  if (pair_count > 0) need(from_to, "from_to");
  for (std::size_t i = 0; i < pair_count; ++i) {
    map.set(Material(from_to[2 * i]), Material(from_to[2 * i + 1]));
  }
  return map;
}

void append(PolygonsHandle& out, std::uint64_t id, Material material, const Box64& cell,
            const Polygon& polygon) {
  if (polygon.size() > std::numeric_limits<std::uint32_t>::max() - out.points.size()) {
    throw BorderError(EL_LIMIT_EXCEEDED, "more than 2^32 - 1 points in one result");
  }
  out.ids.push_back(id);
  out.materials.push_back(material.value());
  out.cells.push_back(to_c(cell));
  for (const Point64 p : polygon) out.points.push_back(to_c(p));
  out.offsets.push_back(static_cast<std::uint32_t>(out.points.size()));
}

void fill(ChangesHandle& out, ChangeSet changes) {
  out.removed.assign(changes.removed.begin(), changes.removed.end());
  for (const ChangeSet::Added& a : changes.added) {
    append(out.added, a.id, a.material, a.cell, a.polygon);
  }
  for (const Box64& cell : changes.cells) out.cells.push_back(to_c(cell));
  for (const auto& [material, twice] : changes.twice_area_delta) {
    out.area_delta.push_back({to_c(twice), material.value(), 0});
  }
  out.source = std::move(changes);
}

std::unique_ptr<ChangesHandle> to_c(ChangeSet changes) {
  auto out = std::make_unique<ChangesHandle>();
  fill(*out, std::move(changes));
  return out;
}

}  // namespace edgeland::capi
