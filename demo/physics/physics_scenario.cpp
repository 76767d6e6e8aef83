#include "physics_scenario.hpp"

#include <algorithm>
#include <chrono>

namespace edgeland::box2d {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A convex octagon of radius r around c (valid by construction for r >= 2): the corners of the
// square of side 2r cut at distance `cut` (1 <= cut < r) along each side.
Polygon octagon(Point64 c, std::int64_t r, std::int64_t cut) {
  const std::int64_t a = r - cut;
  return {{c.x - a, c.y - r}, {c.x + a, c.y - r}, {c.x + r, c.y - a}, {c.x + r, c.y + a},
          {c.x + a, c.y + r}, {c.x - a, c.y + r}, {c.x - r, c.y + a}, {c.x - r, c.y - a}};
}

// The rock's top: hills of period `size / 4` between 9/16 and 11/16 of the height, as a
// polyline of straight pieces (integer points).
PolygonSet hills(std::int64_t size) {
  Polygon rock{{0, 0}, {size, 0}};
  const std::int64_t steps = 32, base = size * 9 / 16, amplitude = size / 8;
  for (std::int64_t i = steps; i >= 0; --i) {
    const std::int64_t x = size * i / steps;
    const std::int64_t phase = (i * 4) % steps;  // a triangle wave, 4 periods
    const std::int64_t up = phase < steps / 2 ? phase : steps - phase;
    rock.push_back({x, base + amplitude * up * 2 / steps});
  }
  return {rock};
}

}  // namespace

std::int64_t PhysicsScenario::Random::in(std::int64_t lo, std::int64_t hi) {
  return lo + static_cast<std::int64_t>(source_.below(static_cast<std::uint64_t>(hi - lo + 1)));
}

// Materials as in `edgeland demo`: 1 bedrock, 2 rock, 3 dirt.
Landscape scene_world(std::int64_t size) {
  Landscape world({{0, 0}, {size, size}});
  world.fill(hills(size), 2);
  world.replace(PolygonSet{{{0, size / 2}, {size, size / 2}, {size, size}, {0, size}}}, 2, 3);
  world.fill(PolygonSet{{{0, 0}, {size, 0}, {size, size / 16}, {0, size / 16}}}, 1);
  for (std::int64_t k = 1; k < 4; ++k)
    world.carve(PolygonSet{octagon({size * k / 4, size * 5 / 16}, size / 20, size / 60)});
  return world;
}

PhysicsMaterials PhysicsScenario::materials() {
  PhysicsMaterials m;
  m.anchored[1] = true;  // bedrock
  return m;
}

GameOptions PhysicsScenario::game_options() {
  GameOptions g;
  g.surface.materials = materials();
  g.surface.border_wall = true;  // nothing leaves the world
  return g;
}

TerrainOptions PhysicsScenario::terrain_options(const PhysicsScenarioOptions& options) {
  TerrainOptions t;
  t.units_per_metre = options.units_per_metre;
  return t;
}

PhysicsScenario::PhysicsScenario(const PhysicsScenarioOptions& options)
    : options_(options),
      random_(options.seed),
      game_(scene_world(options.size), game_options()),
      scene_(game_, terrain_options(options)) {
  drop_bodies(options_.bodies);
}

// Balls and boxes of half a metre, alternately, above the hills.
void PhysicsScenario::drop_bodies(int count) {
  const double half_metre = options_.units_per_metre / 2;
  for (int i = 0; i < count; ++i) {
    const std::int64_t s = options_.size;
    const Point64 at{random_.in(s / 20, s - s / 20), s * 3 / 4 + random_.in(0, s / 8)};
    if (i % 2)
      scene_.drop_ball(at, half_metre);
    else
      scene_.drop_box(at, half_metre);
  }
}

Polygon PhysicsScenario::blast(Point64 centre, std::int64_t radius) {
  return octagon(centre, radius, random_.in(1, radius - 1));
}

int PhysicsScenario::balls_and_boxes() const {
  return static_cast<int>(
      std::count_if(scene_.bodies().begin(), scene_.bodies().end(),
                    [](const SceneBody& b) { return b.kind != BodyKind::kDebris; }));
}

void PhysicsScenario::settle(int frames) {
  for (int i = 0; i < frames; ++i) {
    scene_.step();
    ++stats_.settled;
  }
}

void PhysicsScenario::frame() {
  std::vector<Edit> edits;
  for (int k = 0; k < options_.edits_per_frame; ++k) edits.push_back(edit_near_a_body());
  const auto start = Clock::now();
  const GameUpdate update = game_.apply(edits);
  stats_.game_seconds += since(start);
  stats_.edits += options_.edits_per_frame;
  scene_.apply(update);
  bury_bodies();
  drop_bodies(options_.bodies - balls_and_boxes());
  scene_.step();
  ++stats_.frames;
}

// A blast around a random body, or a fill beside or below it.
Edit PhysicsScenario::edit_near_a_body() {
  const std::vector<SceneBody>& bodies = scene_.bodies();
  const SceneBody& target = bodies[static_cast<std::size_t>(random_.in(0, bodies.size() - 1))];
  const Point64 c = scene_.centre(target.body);
  if (random_.in(0, 3) == 0) {
    const Polygon shape =
        blast({c.x + random_.in(-120, 120), c.y - random_.in(40, 120)}, random_.in(8, 32));
    return Edit::fill(ValidSet(PolygonSet{shape}), static_cast<Material>(random_.in(2, 3)));
  }
  const Polygon shape =
      blast({c.x + random_.in(-60, 60), c.y + random_.in(-80, 20)}, random_.in(8, 48));
  return Edit::carve(ValidSet(PolygonSet{shape}));
}

// The frame's fills buried the bodies they overlap, debris included (the game put solid where
// they are): they leave the play, the one exception to "no centre in solid".
void PhysicsScenario::bury_bodies() {
  stats_.buried += static_cast<int>(scene_.remove_bodies(
      [&](const SceneBody& b) { return game_.buried(scene_.box_of(b.body)); }));
}

}  // namespace edgeland::box2d
