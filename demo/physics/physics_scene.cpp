#include "physics_scene.hpp"

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

std::int64_t PhysicsScene::Random::in(std::int64_t lo, std::int64_t hi) {
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

PhysicsMaterials PhysicsScene::materials() {
  PhysicsMaterials m;
  m.anchored[1] = true;  // bedrock
  return m;
}

GameOptions PhysicsScene::game_options() {
  GameOptions g;
  g.surface.materials = materials();
  g.surface.border_wall = true;  // nothing leaves the world
  return g;
}

TerrainOptions PhysicsScene::terrain_options(const PhysicsSceneOptions& options) {
  TerrainOptions t;
  t.units_per_metre = options.units_per_metre;
  return t;
}

PhysicsScene::PhysicsScene(const PhysicsSceneOptions& options)
    : options_(options),
      random_(options.seed),
      game_(scene_world(options.size), game_options()),
      world_(b2Vec2(0, -10)),
      terrain_(world_, game_, terrain_options(options)) {
  drop_bodies(options_.bodies);
}

void PhysicsScene::drop_bodies(int count) {
  for (int i = 0; i < count; ++i) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    const std::int64_t s = options_.size;
    def.position =
        to_b2(terrain_.units(), {random_.in(s / 20, s - s / 20), s * 3 / 4 + random_.in(0, s / 8)});
    b2Body* body = world_.CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = 0.5f;
    b2PolygonShape box;
    box.SetAsBox(0.5f, 0.5f);
    b2FixtureDef fixture;
    fixture.shape = i % 2 ? static_cast<b2Shape*>(&circle) : static_cast<b2Shape*>(&box);
    fixture.density = 1;
    fixture.friction = 0.5f;
    body->CreateFixture(&fixture);
    bodies_.push_back({body, false, 0});
  }
}

Polygon PhysicsScene::blast(Point64 centre, std::int64_t radius) {
  return octagon(centre, radius, random_.in(1, radius - 1));
}

int PhysicsScene::balls_and_boxes() const {
  return static_cast<int>(
      std::count_if(bodies_.begin(), bodies_.end(), [](const SceneBody& b) { return !b.debris; }));
}

void PhysicsScene::settle(int frames) {
  for (int i = 0; i < frames; ++i) {
    const auto start = Clock::now();
    world_.Step(1.0f / 60.0f, 8, 3);
    stats_.step_seconds += since(start);
    ++stats_.frames;
    ++stats_.settled;
  }
}

// The frame's edits as one batch, the update applied, buried bodies replaced, one step.
void PhysicsScene::frame() {
  std::vector<Edit> edits;
  for (int k = 0; k < options_.edits_per_frame; ++k) edits.push_back(edit_near_a_body());
  auto start = Clock::now();
  const GameUpdate update = game_.apply(edits);
  stats_.game_seconds += since(start);
  stats_.edits += options_.edits_per_frame;
  apply(update);
  bury_bodies();
  drop_bodies(options_.bodies - balls_and_boxes());
  settle(1);
  --stats_.settled;  // settle() counted it
}

// A blast around a random body, or a fill beside or below it.
Edit PhysicsScene::edit_near_a_body() {
  const SceneBody& target = bodies_[static_cast<std::size_t>(random_.in(0, bodies_.size() - 1))];
  const Point64 c = centre(target.body);
  if (random_.in(0, 3) == 0) {
    const Polygon shape =
        blast({c.x + random_.in(-120, 120), c.y - random_.in(40, 120)}, random_.in(8, 32));
    return Edit::fill(ValidSet(PolygonSet{shape}), static_cast<Material>(random_.in(2, 3)));
  }
  const Polygon shape =
      blast({c.x + random_.in(-60, 60), c.y + random_.in(-80, 20)}, random_.in(8, 48));
  return Edit::carve(ValidSet(PolygonSet{shape}));
}

// The update's chains to the terrain, its debris as bodies.
void PhysicsScene::apply(const GameUpdate& update) {
  auto start = Clock::now();
  terrain_.apply(update);
  stats_.collider_seconds += since(start);
  stats_.chains_removed += update.chains.removed.size();
  stats_.chains_added += update.chains.added.size();
  start = Clock::now();
  for (const Debris& d : update.debris) {
    b2Body* debris = make_debris_body(world_, d, terrain_.units());
    bodies_.push_back({debris, true, debris->GetPosition().y});
    ++stats_.detached;
  }
  stats_.debris_seconds += since(start);
}

Box64 PhysicsScene::box_of(b2Body* body) const {
  b2AABB a = body->GetFixtureList()->GetAABB(0);
  for (b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext()) a.Combine(f->GetAABB(0));
  const Point64 lo = terrain_.units().to_world({a.lowerBound.x, a.lowerBound.y});
  const Point64 hi = terrain_.units().to_world({a.upperBound.x, a.upperBound.y});
  return {{lo.x - 1, lo.y - 1}, {hi.x + 1, hi.y + 1}};
}

// The frame's fills buried the bodies they overlap, debris included (the game put solid where
// they are): they leave the play, the one exception to "no centre in solid".
void PhysicsScene::bury_bodies() {
  for (SceneBody& b : bodies_) {
    if (!game_.buried(box_of(b.body))) continue;
    world_.DestroyBody(b.body);
    b.body = nullptr;
    ++stats_.buried;
  }
  std::erase_if(bodies_, [](const SceneBody& b) { return b.body == nullptr; });
}

Point64 PhysicsScene::centre(const b2Body* body) const {
  const b2Vec2 p = body->GetPosition();
  return terrain_.units().to_world({p.x, p.y});
}

std::vector<Point64> PhysicsScene::centres_in_solid() const {
  std::vector<Point64> out;
  for (const SceneBody& b : bodies_) {
    if (b.debris) continue;
    const Point64 c = centre(b.body);
    if (materials().is_solid(land().material_at(c))) out.push_back(c);
  }
  return out;
}

std::vector<Point64> PhysicsScene::centres_outside_world() const {
  std::vector<Point64> out;
  for (const SceneBody& b : bodies_) {
    const Point64 c = centre(b.body);
    if (!land().world().contains(c)) out.push_back(c);
  }
  return out;
}

}  // namespace edgeland::box2d
