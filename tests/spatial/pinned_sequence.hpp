#pragma once
// A fixed edit sequence whose state hash is pinned (issue 15, "Determinism"): the same edits must
// give the same hash under gcc and clang, at -O0, -O2 and -O3. Built from integers only (a
// splitmix64 stream and a table of integer points on a circle), so the sequence itself cannot
// vary between builds. A deliberate change of results (a different canonical decomposition, a
// different snap rounding) changes the pins: update them and say why in the commit.
#include <cstdint>
#include <vector>

#include "edgeland/kernel/splitmix64.hpp"
#include "edgeland/spatial/delta.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::pinned {

// The kernel's generator (splitmix64.hpp) over a state the sequence keeps in a plain integer.
inline std::uint64_t splitmix64(std::uint64_t& s) { return mix64(s += kSplitMix64Gamma); }

// 16 points on a circle of radius 1000 (rounded), counter-clockwise.
inline constexpr std::int64_t kCircle[16][2] = {
    {1000, 0},   {924, 383},  {707, 707},  {383, 924},   {0, 1000},    {-383, 924},
    {-707, 707}, {-924, 383}, {-1000, 0},  {-924, -383}, {-707, -707}, {-383, -924},
    {0, -1000},  {383, -924}, {707, -707}, {924, -383}};

inline Polygon blob(Point64 c, std::int64_t r) {
  Polygon p;
  for (const auto& v : kCircle) p.push_back({c.x + v[0] * r / 1000, c.y + v[1] * r / 1000});
  return p;
}

// The next edit of the sequence: a blob filled, replaced, filled where empty or carved.
inline Edit next_edit(std::uint64_t& seed) {
  const Point64 c{static_cast<std::int64_t>(splitmix64(seed) % 4400) - 150,
                  static_cast<std::int64_t>(splitmix64(seed) % 4400) - 150};
  const std::int64_t r = 20 + static_cast<std::int64_t>(splitmix64(seed) % 120);
  ValidSet shape(PolygonSet{blob(c, r)});
  switch (splitmix64(seed) % 5) {
    case 0:
      return Edit::fill(std::move(shape), 2);
    case 1:
      return Edit::replace(std::move(shape), 1, 3);
    case 2:
      return Edit::fill_empty(std::move(shape), 4);
    default:
      return Edit::carve(std::move(shape));
  }
}

inline constexpr int kEdits = 400;

// 400 edits of every kind on a 4096^2 world filled with material 1, one by one.
inline Landscape run(const LandscapeConfig& config) {
  Landscape l({{0, 0}, {4096, 4096}}, 1, config);
  std::uint64_t seed = 15;
  for (int i = 0; i < kEdits; ++i) apply_edit(l, next_edit(seed));
  return l;
}

// The same 400 edits as frame batches (Landscape::apply_batch) of 1-4 edits, the sizes drawn
// from a stream of their own: each batch rounded once.
inline Landscape run_batches(const LandscapeConfig& config) {
  Landscape l({{0, 0}, {4096, 4096}}, 1, config);
  std::uint64_t seed = 15, sizes = 35;
  for (int i = 0; i < kEdits;) {
    std::vector<Edit> batch;
    const int n = 1 + static_cast<int>(splitmix64(sizes) % 4);
    for (int k = 0; k < n && i < kEdits; ++k, ++i) batch.push_back(next_edit(seed));
    l.apply_batch(batch);
  }
  return l;
}

inline LandscapeConfig kd_tree_config() {
  LandscapeConfig c;
  c.tree = TreeKind::kKdTree;
  c.edge_cap = 64;
  c.merge_below = 20;
  return c;
}

// Regions with their own ids (spatial/README.md, "Regions"): the same edits, each region's ids
// and cut of its own.
inline LandscapeConfig regions_config() {
  LandscapeConfig c;
  c.region_depth = 3;
  c.region_ids = true;
  return c;
}

// Pinned on gcc 12 -O2; every other build must agree. Last changed when ids began to be given
// once per edit, after its splits and merges (spatial/README.md, "Ids"): the same cells and
// polygons as before, but no fresh id goes to a cell the edit replaced again, so ids and the
// next id differ.
inline constexpr std::uint64_t kQuadtreeHash = 0xeaeb4f50cafef240ull;
inline constexpr std::uint64_t kKdTreeHash = 0x88c6cb00a6c83cd3ull;
// Pinned when regions came (issue 37); the two above are the same with them off.
inline constexpr std::uint64_t kRegionsHash = 0x1cadce143d958fc8ull;
// The same edits in frame batches (run_batches): pinned when batches came (issue 35 point 2).
inline constexpr std::uint64_t kQuadtreeBatchHash = 0xdccf7cada8d4e794ull;
inline constexpr std::uint64_t kKdTreeBatchHash = 0xa992c3fd480eb2cfull;
inline constexpr std::uint64_t kRegionsBatchHash = 0x18af83bb1a78398aull;
// The algorithm version (delta.hpp) these hashes belong to: a change of the pins is a change of
// how edits round, so kAlgorithmVersion goes up with it (peers of different versions must not
// exchange COMMAND deltas). LandscapeDeterminism.PinsBelongToTheAlgorithmVersion checks both
// move together.
inline constexpr std::uint32_t kPinnedAlgorithmVersion = 1;

}  // namespace edgeland::pinned
