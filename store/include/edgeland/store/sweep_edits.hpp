#pragma once
// The streaming run's edits (store/README.md, "StreamingWorld"; `edgeland stream`, the store
// tests): a world built region by region, then tunnelled through again, so that a run under a
// memory budget loads, edits, evicts and later loads back every region. Edit i is a function of
// i alone (integers only), so a run resumed after a crash goes on with the same edits.
#include <cstddef>
#include <cstdint>

#include "edgeland/kernel/export.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland::store {

class EDGELAND_EXPORT SweepEdits {
 public:
  // A world of side `side` (a multiple of 128) with regions 2^depth to a side. About `sides` + 4
  // vertices come with each fill.
  SweepEdits(std::int64_t side, int region_depth, std::int64_t sides = 96);
  // The world's box and configuration (region_ids on).
  Box64 world() const { return {{0, 0}, {side_, side_}}; }
  LandscapeConfig config() const;
  // First a fill of a `sides`-gon at every slot of a 128-unit lattice, region after region; then
  // a tunnel (a capsule) from every fourth slot, region after region again.
  std::size_t size() const noexcept { return slots_ + slots_ / 4; }
  Edit at(std::size_t i) const;

 private:
  Point64 slot(std::size_t k) const;
  std::int64_t side_, per_region_side_, regions_side_;
  int depth_;
  std::int64_t sides_;
  std::size_t slots_;
};

}  // namespace edgeland::store
