#pragma once
// Bigger deterministic worlds for the game layer's tests: a layered world (bedrock, rock, dirt)
// hit by many random blasts, tunnels and fills, from a seeded generator, so that cells split
// and merge many times over.
#include <cstdint>
#include <functional>

#include "edgeland/kernel/splitmix64.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "shape_builders.hpp"

namespace edgeland::test {

// The project's one seeded generator (kernel/: splitmix64.hpp) with draws in [lo, hi].
class SplitMix : public edgeland::SplitMix64 {
 public:
  using edgeland::SplitMix64::SplitMix64;
  std::int64_t in(std::int64_t lo, std::int64_t hi) {  // [lo, hi]
    return lo + static_cast<std::int64_t>(below(static_cast<std::uint64_t>(hi - lo + 1)));
  }
};

// A convex blast of about radius r around c: the hull of random points on a square ring.
inline Polygon blast(SplitMix& rng, Point64 c, std::int64_t r) {
  std::vector<Point64> pts;
  for (int i = 0; i < 12; ++i) pts.push_back({c.x + rng.in(-r, r), c.y + rng.in(-r, r)});
  for (const Point64 d : {Point64{r, 0}, Point64{-r, 0}, Point64{0, r}, Point64{0, -r}})
    pts.push_back({c.x + d.x, c.y + d.y});
  return convex_hull(pts);
}

// A layered world of side `size`: bedrock (3) at the bottom, rock (1), dirt (2) above.
inline Landscape layered_world(std::int64_t size, const LandscapeConfig& config = {}) {
  Landscape world({{0, 0}, {size, size}}, kEmpty, config);
  world.fill(PolygonSet{{{0, 0}, {size, 0}, {size, size / 2}, {0, size / 2}}}, 1);
  world.fill(PolygonSet{{{0, size / 2}, {size, size / 2}, {size, size * 5 / 8}, {0, size * 5 / 8}}},
             2);
  world.fill(PolygonSet{{{0, 0}, {size, 0}, {size, size / 16}, {0, size / 16}}}, 3);
  return world;
}

// `edits` random edits of the world: mostly carves, some fills and replaces; `after` sees each
// change set.
inline void random_edits(Landscape& world, std::uint64_t seed, int edits,
                         const std::function<void(const ChangeSet&)>& after) {
  SplitMix rng(seed);
  const Box64 w = world.world();
  const std::int64_t size = w.max.x - w.min.x;
  for (int i = 0; i < edits; ++i) {
    const Point64 c{rng.in(w.min.x, w.max.x), rng.in(w.min.y, w.min.y + size * 3 / 4)};
    const std::int64_t r = rng.in(3, size / 12);
    const PolygonSet shape{blast(rng, c, r)};
    const std::int64_t kind = rng.in(0, 9);
    ChangeSet changes;
    if (kind < 6)
      changes = world.carve(shape);
    else if (kind < 8)
      changes = world.fill(shape, static_cast<Material>(rng.in(1, 2)));
    else if (kind < 9)
      changes = world.fill_empty(shape, 4);
    else
      changes = world.replace(shape, 1, 2);
    after(changes);
  }
}

}  // namespace edgeland::test
