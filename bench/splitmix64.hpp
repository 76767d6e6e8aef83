#pragma once
// The benchmarks' seeded inputs come from the project's one generator (demo/: splitmix64.hpp;
// std:: distributions differ between standard libraries, these inputs must not), with a draw in
// [0, 1) for the workloads that place points with doubles.
#include <cstdint>

#include "edgeland/demo/splitmix64.hpp"

namespace edgeland::bench {

class SplitMix64 : public demo::SplitMix64 {
 public:
  using demo::SplitMix64::SplitMix64;
  // Uniform in [0, 1) (bench/ only: the library never sees a double).
  double unit() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
};

}  // namespace edgeland::bench
