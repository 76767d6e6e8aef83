#include "demo_actions.hpp"

#include <algorithm>

#include "demo_shapes.hpp"
#include "integer_trig.hpp"

namespace edgeland::cli::demo {
namespace {

// Sizes are in 1/8192 of the world's width, so the demo looks the same at any world size.
struct Scale {
  const Box64& world;
  std::int64_t operator()(std::int64_t units) const {
    return std::max<std::int64_t>(1, (world.max.x - world.min.x) * units / 8192);
  }
};

// A point in the ground: anywhere across, between the bottom and the surface there.
Point64 point_in_ground(const Box64& world, const Terrain& terrain, SplitMix64& random) {
  const std::int64_t x = random.between(world.min.x, world.max.x);
  const std::int64_t top = std::max(world.min.y, terrain.surface.y_at(x, world));
  return {x, random.between(world.min.y, std::min(top, world.max.y))};
}

// A random walk of `steps` steps from `start`, its heading drifting a little each step;
// step(from, to, heading) is called for each.
template <class Step>
void walk(Point64 start, int steps, std::int64_t length, SplitMix64& random, Step&& step) {
  int heading = static_cast<int>(random.between(0, kFullTurn - 1));
  Point64 at = start;
  for (int i = 0; i < steps; ++i) {
    heading += static_cast<int>(random.between(-14, 14));
    const Point64 next = polar(at, length, heading);
    step(at, next, heading);
    at = next;
  }
}

}  // namespace

ActionCounts run_actions(DemoEditor& editor, const Box64& world, const Terrain& terrain,
                         std::size_t edits, SplitMix64& random) {
  const Scale s{world};
  ActionCounts counts;
  const std::size_t target = editor.edits() + edits;
  const auto left = [&] { return static_cast<int>(target - std::min(target, editor.edits())); };
  while (left() > 0) {
    const Point64 at = point_in_ground(world, terrain, random);
    const std::int64_t roll = random.between(0, 99);
    if (roll < 60) {
      const std::int64_t r = s(random.between(8, 64));
      editor.carve(rough_ngon(at, r, static_cast<int>(random.between(8, 24)), 30, random));
      ++counts.explosions;
    } else if (roll < 74) {
      const std::int64_t r = s(random.between(10, 24));
      walk(at, std::min(left(), static_cast<int>(random.between(4, 10))), s(random.between(40, 80)),
           random, [&](Point64 a, Point64 b, int heading) {
             editor.carve(capsule(a, b, heading, r));
             ++counts.tunnel_steps;
           });
    } else if (roll < 82) {
      editor.fill_empty(rough_ngon(at, s(random.between(30, 140)), 20, 20, random), kWater);
      ++counts.floods;
    } else if (roll < 90) {
      const std::int64_t r = s(random.between(6, 14));
      walk(at, std::min(left(), static_cast<int>(random.between(3, 7))), s(random.between(30, 60)),
           random, [&](Point64 a, Point64 b, int heading) {
             editor.replace(capsule(a, b, heading, r), kRock, kOre);
             ++counts.vein_steps;
           });
    } else if (roll < 94) {
      editor.fill(rough_ngon(at, s(random.between(30, 120)), 16, 25, random), kDirt);
      ++counts.landslides;
    } else {
      editor.fill_empty(rough_ngon(at, s(random.between(30, 140)), 16, 25, random), kSand);
      ++counts.drifts;
    }
  }
  return counts;
}

}  // namespace edgeland::cli::demo
