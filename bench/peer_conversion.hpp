#pragma once
// Shared helpers for turning a peer's output back into integer rings (PeerRings contract).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::bench {

// Nearest integer, halves away from zero.
inline std::int64_t round_coord(double v) { return static_cast<std::int64_t>(std::llround(v)); }

// Drops the closing duplicate of a closed ring and reverses clockwise rings. A ring of zero
// signed area is left as it is (validate will reject it).
inline Ring as_open_ccw(Ring ring) {
  if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
  if (twice_signed_area(ring) < 0) std::reverse(ring.begin(), ring.end());
  return ring;
}

}  // namespace edgeland::bench
