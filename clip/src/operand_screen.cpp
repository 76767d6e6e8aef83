#include "operand_screen.hpp"

#include <cstdint>

#include "edgeland/kernel/predicates.hpp"
#include "point_key.hpp"

namespace edgeland::detail {

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
    std::uint64_t least_key = point_key(ring[0]);
    std::size_t least = 0;
    for (std::size_t i = 1; i < n; ++i) {
      const std::uint64_t k = point_key(ring[i]);
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
