#pragma once
// A point as one 64-bit key with the same (lexicographic) order, for sorting and comparing
// points by one integer: every coordinate the clipper handles is within kCoordBound = 2^31 - 1
// (callers check or know it), so c + 2^31 fits in 32 bits.
#include <cstdint>

#include "edgeland/kernel/point.hpp"

namespace edgeland::detail {

inline std::uint64_t point_key(Point64 p) {
  return (static_cast<std::uint64_t>(p.x + kCoordBound + 1) << 32) |
         static_cast<std::uint64_t>(p.y + kCoordBound + 1);
}

// The point of a key: point_of(point_key(p)) == p.
inline Point64 point_of(std::uint64_t key) {
  return {static_cast<std::int64_t>(key >> 32) - kCoordBound - 1,
          static_cast<std::int64_t>(key & 0xffffffffu) - kCoordBound - 1};
}

}  // namespace edgeland::detail
