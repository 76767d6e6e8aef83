#include "edgeland/demo/actions.hpp"

#include <algorithm>

#include "edgeland/demo/integer_trig.hpp"
#include "edgeland/demo/shapes.hpp"
#include "edgeland/kernel/shapes.hpp"

namespace edgeland::demo {
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

// The actions, one function each. Every random number is drawn in its own statement: the order
// of evaluation of function arguments is unspecified, and the demo must be the same world on
// every compiler.
class Actions {
 public:
  Actions(DemoEditor& editor, const Box64& world, SplitMix64& random)
      : editor_(editor), s_{world}, random_(random) {}

  void explode(Point64 at) {
    const std::int64_t r = s_(random_.between(8, 64));
    const auto n = static_cast<int>(random_.between(8, 24));
    editor_.carve(rough_ngon(at, r, n, 30, random_));
    ++counts_.explosions;
  }
  void dig_tunnel(Point64 at, int max_steps) {
    const std::int64_t r = s_(random_.between(10, 24));
    const auto steps = std::min(max_steps, static_cast<int>(random_.between(4, 10)));
    walk(at, steps, s_(random_.between(40, 80)), [&](Point64 a, Point64 b) {
      editor_.carve(capsule(a, b, r));
      ++counts_.tunnel_steps;
    });
  }
  void flood(Point64 at) {
    const std::int64_t r = s_(random_.between(30, 140));
    editor_.fill_empty(rough_ngon(at, r, 20, 20, random_), kWater);
    ++counts_.floods;
  }
  void lay_vein(Point64 at, int max_steps) {
    const std::int64_t r = s_(random_.between(6, 14));
    const auto steps = std::min(max_steps, static_cast<int>(random_.between(3, 7)));
    walk(at, steps, s_(random_.between(30, 60)), [&](Point64 a, Point64 b) {
      editor_.replace(capsule(a, b, r), kRock, kOre);
      ++counts_.vein_steps;
    });
  }
  void landslide(Point64 at) {
    const std::int64_t r = s_(random_.between(30, 120));
    editor_.fill(rough_ngon(at, r, 16, 25, random_), kDirt);
    ++counts_.landslides;
  }
  void drift(Point64 at) {
    const std::int64_t r = s_(random_.between(30, 140));
    editor_.fill_empty(rough_ngon(at, r, 16, 25, random_), kSand);
    ++counts_.drifts;
  }

  const ActionCounts& counts() const noexcept { return counts_; }

 private:
  // A random walk of `steps` steps of `length` from `start`, its heading drifting a little each
  // step; step(from, to) is called for each.
  template <class Step>
  void walk(Point64 start, int steps, std::int64_t length, Step&& step) {
    int heading = static_cast<int>(random_.between(0, kFullTurn - 1));
    Point64 at = start;
    for (int i = 0; i < steps; ++i) {
      heading += static_cast<int>(random_.between(-14, 14));
      const Point64 next = polar(at, length, heading);
      step(at, next);
      at = next;
    }
  }

  DemoEditor& editor_;
  Scale s_;
  SplitMix64& random_;
  ActionCounts counts_;
};

}  // namespace

ActionCounts run_actions(DemoEditor& editor, const Box64& world, const Terrain& terrain,
                         std::size_t edits, SplitMix64& random) {
  Actions actions(editor, world, random);
  const std::size_t target = editor.edits() + edits;
  const auto left = [&] { return static_cast<int>(target - std::min(target, editor.edits())); };
  while (left() > 0) {
    const Point64 at = point_in_ground(world, terrain, random);
    const std::int64_t roll = random.between(0, 99);  // percent of each action below
    if (roll < 60) {
      actions.explode(at);
    } else if (roll < 74) {
      actions.dig_tunnel(at, left());
    } else if (roll < 82) {
      actions.flood(at);
    } else if (roll < 90) {
      actions.lay_vein(at, left());
    } else if (roll < 94) {
      actions.landslide(at);
    } else {
      actions.drift(at);
    }
  }
  return actions.counts();
}

}  // namespace edgeland::demo
