#pragma once
// The mirror script of tests/mirror/README.md in C++: the reference every language's run is
// compared with.
#include <cstdint>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "edgeland/kernel/shapes.hpp"
#include "edgeland/kernel/splitmix64.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::mirror {

inline constexpr int kFrames = 5000;

// splitmix64 from s = 36 (README.md, "Random numbers"): the kernel's generator; the other
// languages write it out.
class Random {
 public:
  std::int64_t below(std::int64_t n) {
    return static_cast<std::int64_t>(random_.below(static_cast<std::uint64_t>(n)));
  }

 private:
  SplitMix64 random_{36};
};

// The polygons by id, kept from change sets only.
using Mirror = std::map<PolygonId, std::pair<Material, Polygon>>;

inline void apply_changes(Mirror& mirror, const ChangeSet& changes) {
  for (const PolygonId id : changes.removed) mirror.erase(id);
  for (const ChangeSet::Added& a : changes.added) mirror[a.id] = {a.material, a.polygon};
}

inline Mirror polygons_of(const Landscape& world) {
  Mirror out;
  world.polygons_in(world.world(), [&](const PolygonView& v) {
    out[v.id] = {v.material, *v.polygon};
    return true;
  });
  return out;
}

inline Polygon draw_shape(Random& random) {
  const std::int64_t kind = random.below(3);
  const Point64 c{random.below(2176) - 64, random.below(1152) - 64};
  const std::int64_t r = 4 + random.below(60);
  if (kind == 0) return circle(c, r);
  if (kind == 1) {
    const std::int64_t h = 1 + r / 2;
    return box_shape({{c.x - r, c.y - h}, {c.x + r, c.y + h}});
  }
  const std::int64_t sides = 3 + random.below(6);
  return regular_polygon(c, r, sides, Turn{random.below(16), 16});
}

// One edit of the script on the world; its change set.
inline ChangeSet draw_edit(Random& random, Landscape& world) {
  const std::int64_t op = random.below(5);
  const PolygonSet shape{draw_shape(random)};
  switch (op) {
    case 0:
      return world.carve(shape);
    case 1:
      return world.fill(shape, Material(1 + random.below(4)));
    case 2:
      return world.fill_empty(shape, Material(1 + random.below(4)));
    case 3: {
      const Material from(random.below(5));
      return world.replace(shape, from, Material(random.below(5)));
    }
    default: {
      MaterialMap map;
      for (int pair = 0; pair < 2; ++pair) {
        const Material from(random.below(5));
        map.set(from, Material(random.below(5)));
      }
      return world.relabel(shape, map);
    }
  }
}

}  // namespace edgeland::mirror
