#pragma once
// Boxes grown by a margin: the clipper's candidate searches look a unit or two beyond a box,
// since a snapped segment stays within half a unit of where it was.
#include <cstdint>

#include "edgeland/kernel/bbox.hpp"

namespace edgeland::detail {

// b with every side moved out by `by` (coordinates stay within 64 bits: b's are within the
// input range, far below 2^62).
constexpr Box64 grown(const Box64& b, std::int64_t by) {
  return {{b.min.x - by, b.min.y - by}, {b.max.x + by, b.max.y + by}};
}

// A box that contains the whole (closed) pixel of p.
constexpr Box64 pixel_box(Point64 p) { return grown(Box64{p, p}, 1); }

}  // namespace edgeland::detail
