#pragma once
// A double uniform in [0, 1) from the project's one seeded generator (the kernel's SplitMix64;
// std:: distributions differ between standard libraries, these inputs must not), for the
// workloads that place points with doubles (bench/ only: the library never sees a double).
#include "edgeland/kernel/splitmix64.hpp"

namespace edgeland::bench {

// The top 53 bits of the next draw as a fraction.
inline double unit_draw(SplitMix64& random) noexcept {
  return static_cast<double>(random.next() >> 11) * 0x1.0p-53;
}

}  // namespace edgeland::bench
