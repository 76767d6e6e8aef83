#pragma once
// The integer hash of the landscape's canonical form (spatial/README.md, "Determinism"):
// splitmix64 finalisation over each value in a fixed order, so equal states hash equally on
// every compiler and platform.
#include <cstdint>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/splitmix64.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland::detail {

class StateHash {
 public:
  explicit StateHash(std::uint64_t seed = 0x6564676c616e6421ull) : h_(seed) {}
  StateHash& add(std::uint64_t v) noexcept {
    h_ = mix64(h_ ^ (v + kSplitMix64Gamma + (h_ << 6) + (h_ >> 2)));
    return *this;
  }
  StateHash& add(std::int64_t v) noexcept { return add(static_cast<std::uint64_t>(v)); }
  StateHash& add(Point64 p) noexcept { return add(p.x).add(p.y); }
  StateHash& add(const Box64& b) noexcept { return add(b.min).add(b.max); }
  std::uint64_t value() const noexcept { return h_; }

 private:
  std::uint64_t h_;
};

// The world box and the configuration, the start of the state hash and all of the world hash
// (Landscape::world_hash). The region options only when they are on: without them the hashes
// are what they always were (every pin stands).
inline void add_world(StateHash& h, const Box64& world, const LandscapeConfig& c) noexcept {
  h.add(world)
      .add(static_cast<std::uint64_t>(c.tree))
      .add(static_cast<std::uint64_t>(c.edge_cap))
      .add(static_cast<std::uint64_t>(c.merge_below))
      .add(static_cast<std::uint64_t>(c.min_cell_size))
      .add(static_cast<std::uint64_t>(static_cast<std::int64_t>(c.grid_depth)));
  if (c.region_depth >= 0)
    h.add(static_cast<std::uint64_t>(c.region_depth)).add(std::uint64_t{c.region_ids});
}

}  // namespace edgeland::detail
