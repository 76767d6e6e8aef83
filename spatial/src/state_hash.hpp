#pragma once
// The integer hash of the landscape's canonical form (spatial/README.md, "Determinism"):
// splitmix64 finalisation over each value in a fixed order, so equal states hash equally on
// every compiler and platform.
#include <cstdint>

#include "edgeland/kernel/bbox.hpp"

namespace edgeland::detail {

class StateHash {
 public:
  explicit StateHash(std::uint64_t seed = 0x6564676c616e6421ull) : h_(seed) {}
  StateHash& add(std::uint64_t v) noexcept {
    std::uint64_t z = h_ ^ (v + 0x9E3779B97F4A7C15ull + (h_ << 6) + (h_ >> 2));
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    h_ = z ^ (z >> 31);
    return *this;
  }
  StateHash& add(std::int64_t v) noexcept { return add(static_cast<std::uint64_t>(v)); }
  StateHash& add(Point64 p) noexcept { return add(p.x).add(p.y); }
  StateHash& add(const Box64& b) noexcept { return add(b.min).add(b.max); }
  std::uint64_t value() const noexcept { return h_; }

 private:
  std::uint64_t h_;
};

}  // namespace edgeland::detail
