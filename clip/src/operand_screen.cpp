#include "operand_screen.hpp"

#include <cstdint>

#include "edgeland/kernel/predicates.hpp"

namespace edgeland::detail {

namespace {

// The ring's points as 64-bit keys ordered like the points (point_set.hpp and the plane graph
// use the same map): in range, c + 2^31 fits 32 bits.
std::uint64_t key_of(Point64 p) {
  return (static_cast<std::uint64_t>(p.x + kCoordBound + 1) << 32) |
         static_cast<std::uint64_t>(p.y + kCoordBound + 1);
}

}  // namespace

bool rings_pass_screen(const PolygonSet& set) {
  for (const Ring& ring : set) {
    const std::size_t n = ring.size();
    if (n < 3) return false;
    // Range and repeats first, with no early exit (the loop stays branch-free); the least
    // point only once every coordinate is known to be in range.
    bool bad = ring[n - 1] == ring[0];
    for (std::size_t i = 0; i < n; ++i) {
      const Point64 p = ring[i];
      bad |= !in_range(p);
      if (i + 1 < n) bad |= p == ring[i + 1];
    }
    if (bad) return false;
    std::uint64_t least_key = key_of(ring[0]);
    std::size_t least = 0;
    for (std::size_t i = 1; i < n; ++i) {
      const std::uint64_t k = key_of(ring[i]);
      if (k < least_key) {
        least_key = k;
        least = i;
      }
    }
    if (orientation(ring[least == 0 ? n - 1 : least - 1], ring[least],
                    ring[least + 1 == n ? 0 : least + 1]) != Orientation::kCounterClockwise)
      return false;
  }
  return true;
}

}  // namespace edgeland::detail
