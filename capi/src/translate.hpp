#pragma once
// C++ values to the C structs of edgeland.h and back: field for field, nothing computed.
#include <cstdint>
#include <memory>
#include <vector>

#include "border.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/spatial/types.hpp"
#include "handles.hpp"

namespace edgeland::capi {

el_int128 to_c(Int128 v) noexcept;
inline el_point to_c(Point64 p) noexcept { return {p.x, p.y}; }
inline el_box to_c(const Box64& b) noexcept { return {to_c(b.min), to_c(b.max)}; }
el_crossing to_c(const MaterialCrossing& c) noexcept;

Point64 point_of(const el_point* p, const char* name);
Box64 box_of(const el_box* b, const char* name);
// A CSR polygon set as the C++ value (copied; the shape is validated where it is used).
PolygonSet polygon_set_of(const std::int64_t* xy, const std::uint32_t* offsets,
                          std::size_t polygon_count);

// A relabel's pairs (from_to[2i] -> from_to[2i + 1], a later pair for one material wins), each
// material checked (InvalidMaterial).
MaterialMap material_map_of(const std::int32_t* from_to, std::size_t pair_count);

// Appends one polygon to the arrays (EL_LIMIT_EXCEEDED past 2^32 - 1 points: offsets are 32 bits).
void append(PolygonsHandle& out, std::uint64_t id, Material material, const Box64& cell,
            const Polygon& polygon);
// The arrays of a change set, which then keeps the C++ value too.
std::unique_ptr<ChangesHandle> to_c(ChangeSet changes);
void fill(ChangesHandle& out, ChangeSet changes);

// The handle made and owned here, released to the caller's out-parameter only when everything
// succeeded (so a failure leaves *out as it was).
template <class C, class T>
void hand_out(std::unique_ptr<T> made, C** out) {
  *out = handle<C>(made.release());
}

// The object behind a required handle argument: EL_NULL_ARGUMENT naming it when NULL.
template <class C>
auto& object_of(C* h, const char* name) {
  return need(object(h), name);
}

}  // namespace edgeland::capi
