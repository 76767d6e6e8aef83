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

TerrainOptions PhysicsScene::terrain_options(const PhysicsSceneOptions& options) {
  TerrainOptions t;
  t.surface.materials = materials();
  t.surface.border_wall = true;  // nothing leaves the world
  t.units.units_per_engine_unit = options.units_per_metre;
  return t;
}

PhysicsScene::PhysicsScene(const PhysicsSceneOptions& options)
    : options_(options),
      random_(options.seed),
      land_(scene_world(options.size)),
      world_(b2Vec2(0, -10)),
      terrain_(world_, land_, terrain_options(options)),
      islands_(land_, materials()) {
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
  }
}

void PhysicsScene::frame() {
  for (int k = 0; k < options_.edits_per_frame; ++k) edit_near_a_body();
  settle(1);
}

// A blast around a random body, or a fill beside or below it; bodies a fill buries leave the
// play and new ones drop from the sky, so about `bodies` are always in play.
void PhysicsScene::edit_near_a_body() {
  const SceneBody& target = bodies_[static_cast<std::size_t>(random_.in(0, bodies_.size() - 1))];
  const Point64 c = centre(target.body);
  if (random_.in(0, 3) == 0) {
    const PolygonSet shape{
        blast({c.x + random_.in(-120, 120), c.y - random_.in(40, 120)}, random_.in(8, 32))};
    bury_bodies_under(shape);
    const auto start = Clock::now();
    const ChangeSet changes = land_.fill(shape, static_cast<Material>(random_.in(2, 3)));
    stats_.edit_seconds += since(start);
    apply(changes);
    drop_bodies(options_.bodies - balls_and_boxes());
  } else {
    const PolygonSet shape{
        blast({c.x + random_.in(-60, 60), c.y + random_.in(-80, 20)}, random_.in(8, 48))};
    const auto start = Clock::now();
    const ChangeSet changes = land_.carve(shape);
    stats_.edit_seconds += since(start);
    apply(changes);
  }
}

// Every tracker sees every edit, the detaches too.
void PhysicsScene::apply(const ChangeSet& changes) {
  ++stats_.edits;
  auto start = Clock::now();
  const ChainUpdate u = terrain_.update(land_, changes);
  stats_.collider_seconds += since(start);
  stats_.chains_removed += u.removed.size();
  stats_.chains_added += u.added.size();
  start = Clock::now();
  std::vector<Island> pending = islands_.update(land_, changes);
  stats_.island_seconds += since(start);
  detach_islands(std::move(pending));
}

// The loop of islands.hpp: a detach can re-cut the cells of another island found by the same
// edit; that one is then stale, and the tracker reports it again.
void PhysicsScene::detach_islands(std::vector<Island> pending) {
  while (!pending.empty()) {
    const Island island = std::move(pending.back());
    pending.pop_back();
    DetachedIsland detached;
    try {
      detached = detach(land_, island);
    } catch (const StaleIsland&) {
      continue;
    }
    terrain_.update(land_, detached.changes);
    for (Island& again : islands_.update(land_, detached.changes))
      pending.push_back(std::move(again));
    b2Body* debris = make_debris_body(world_, detached, terrain_.units());
    bodies_.push_back({debris, true, debris->GetPosition().y});
    ++stats_.detached;
  }
}

Box64 PhysicsScene::box_of(b2Body* body) const {
  b2AABB a = body->GetFixtureList()->GetAABB(0);
  for (b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext()) a.Combine(f->GetAABB(0));
  const Point64 lo = terrain_.units().to_world({a.lowerBound.x, a.lowerBound.y});
  const Point64 hi = terrain_.units().to_world({a.upperBound.x, a.upperBound.y});
  return {{lo.x - 1, lo.y - 1}, {hi.x + 1, hi.y + 1}};
}

// A fill buries the bodies it overlaps, debris included (the game put solid where they are):
// they leave the play, the one exception to "no centre in solid".
void PhysicsScene::bury_bodies_under(const PolygonSet& shape) {
  Landscape probe(land_.world());
  probe.fill(shape, 1);
  for (SceneBody& b : bodies_) {
    if (probe.overlaps(box_of(b.body)).empty()) continue;
    world_.DestroyBody(b.body);
    b.body = nullptr;
    ++stats_.buried;
  }
  bodies_.erase(std::remove_if(bodies_.begin(), bodies_.end(),
                               [](const SceneBody& b) { return b.body == nullptr; }),
                bodies_.end());
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
    if (materials().is_solid(land_.material_at(c))) out.push_back(c);
  }
  return out;
}

std::vector<Point64> PhysicsScene::centres_outside_world() const {
  std::vector<Point64> out;
  for (const SceneBody& b : bodies_) {
    const Point64 c = centre(b.body);
    if (!land_.world().contains(c)) out.push_back(c);
  }
  return out;
}

}  // namespace edgeland::box2d
