#include "physics_scene.hpp"

#include <chrono>

namespace edgeland::box2d {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

PhysicsScene::PhysicsScene(const GameDriver& game, const TerrainOptions& options)
    : game_(game), world_(b2Vec2(0, -10)), terrain_(world_, game, options) {}

void PhysicsScene::apply(const GameUpdate& update) {
  auto start = Clock::now();
  terrain_.apply(update);
  stats_.collider_seconds += since(start);
  stats_.chains_removed += update.chains.removed.size();
  stats_.chains_added += update.chains.added.size();
  start = Clock::now();
  for (const Debris& d : update.debris) {
    b2Body* body = make_debris_body(world_, d, terrain_.units());
    bodies_.push_back(
        {body, BodyKind::kDebris, 0, body->GetPosition().y, d.meshes, to_double(d.centroid)});
    ++stats_.detached;
  }
  stats_.debris_seconds += since(start);
}

void PhysicsScene::add_body(const b2BodyDef& def, const b2Shape& shape, BodyKind kind, double size,
                            const BodySurface& surface) {
  b2Body* body = world_.CreateBody(&def);
  b2FixtureDef fixture;
  fixture.shape = &shape;
  fixture.density = 1;
  fixture.friction = surface.friction;
  fixture.restitution = surface.restitution;
  body->CreateFixture(&fixture);
  bodies_.push_back({body, kind, size});
}

void PhysicsScene::drop_ball(Point64 at, double radius, const BodySurface& surface) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = to_b2(terrain_.units(), at);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(terrain_.units().length_to_engine(radius));
  add_body(def, circle, BodyKind::kBall, radius, surface);
}

void PhysicsScene::drop_box(Point64 at, double half, float angle, const BodySurface& surface) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = to_b2(terrain_.units(), at);
  def.angle = angle;
  b2PolygonShape box;
  const auto h = static_cast<float>(terrain_.units().length_to_engine(half));
  box.SetAsBox(h, h);
  add_body(def, box, BodyKind::kBox, half, surface);
}

void PhysicsScene::step(float seconds) {
  const auto start = Clock::now();
  world_.Step(seconds, 8, 3);
  stats_.step_seconds += since(start);
  ++stats_.steps;
}

std::size_t PhysicsScene::remove_bodies(const std::function<bool(const SceneBody&)>& which) {
  return std::erase_if(bodies_, [&](const SceneBody& b) {
    if (!which(b)) return false;
    world_.DestroyBody(b.body);
    return true;
  });
}

std::vector<Point64> PhysicsScene::centres_in_solid() const {
  const PhysicsMaterials& materials = game_.options().surface.materials;
  std::vector<Point64> out;
  for (const SceneBody& b : bodies_) {
    if (b.kind == BodyKind::kDebris) continue;
    const Point64 c = centre(b.body);
    if (materials.is_solid(land().material_at(c))) out.push_back(c);
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

Point64 PhysicsScene::centre(const b2Body* body) const {
  const b2Vec2 p = body->GetPosition();
  return terrain_.units().to_world({p.x, p.y});
}

EngineVec PhysicsScene::position(const b2Body* body) const {
  const b2Vec2 p = body->GetPosition();
  const EngineUnits& units = terrain_.units();
  return {static_cast<double>(units.origin.x) + units.to_world_length(p.x),
          static_cast<double>(units.origin.y) + units.to_world_length(p.y)};
}

Box64 PhysicsScene::box_of(const b2Body* body) const {
  b2AABB a = body->GetFixtureList()->GetAABB(0);
  for (const b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext()) a.Combine(f->GetAABB(0));
  const Point64 lo = terrain_.units().to_world({a.lowerBound.x, a.lowerBound.y});
  const Point64 hi = terrain_.units().to_world({a.upperBound.x, a.upperBound.y});
  return {{lo.x - 1, lo.y - 1}, {hi.x + 1, hi.y + 1}};
}

}  // namespace edgeland::box2d
