#include "physics.hpp"

#include <algorithm>
#include <cmath>

namespace edgeland::play {

Physics::Physics(const GameDriver& game, double units_per_metre)
    : box_(game.landscape().world()),
      units_{game.landscape().world().min, units_per_metre},
      world_(std::make_unique<b2World>(b2Vec2(0.0f, -10.0f))) {
  box2d::TerrainOptions options;
  options.units_per_metre = units_per_metre;
  terrain_.emplace(*world_, game, options);
}

b2Vec2 Physics::metres(Point64 p) const { return box2d::to_b2(units_, p); }

double Physics::world_x(float metres_x) const {
  return static_cast<double>(box_.min.x) + metres_x * units_.units_per_engine_unit;
}
double Physics::world_y(float metres_y) const {
  return static_cast<double>(box_.min.y) + metres_y * units_.units_per_engine_unit;
}

Point64 Physics::centre(const DynamicBody& body) const {
  const b2Vec2 p = body.body->GetPosition();
  return {std::llround(world_x(p.x)), std::llround(world_y(p.y))};
}

// Between two steps: no body ever sees a missing wall.
void Physics::apply(const GameUpdate& update) {
  terrain_->apply(update);
  for (const Debris& d : update.debris) add_debris(d);
}

void Physics::drop_ball(Point64 at, double radius) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = metres(at);
  b2Body* body = world_->CreateBody(&def);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(radius / units_.units_per_engine_unit);
  b2FixtureDef fixture;
  fixture.shape = &circle;
  fixture.density = 1;
  fixture.friction = 0.4f;
  fixture.restitution = 0.2f;
  body->CreateFixture(&fixture);
  bodies_.push_back({body, BodyKind::kBall, radius});
}

void Physics::drop_box(Point64 at, double half) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = metres(at);
  def.angle = 0.3f;
  b2Body* body = world_->CreateBody(&def);
  b2PolygonShape box;
  const auto h = static_cast<float>(half / units_.units_per_engine_unit);
  box.SetAsBox(h, h);
  b2FixtureDef fixture;
  fixture.shape = &box;
  fixture.density = 1;
  fixture.friction = 0.5f;
  body->CreateFixture(&fixture);
  bodies_.push_back({body, BodyKind::kBox, half});
}

// The debris body, and its meshes (the driver's) around the body's origin for drawing.
void Physics::add_debris(const Debris& d) {
  DynamicBody debris{box2d::make_debris_body(*world_, d, units_), BodyKind::kDebris, 0};
  const EngineVec c = to_double(d.centroid);
  for (const PolygonMesh& mesh : d.meshes) {
    DynamicBody::Piece piece{mesh.material, {}, {}};
    for (const Point64& p : mesh.vertices)
      piece.vertices.emplace_back(static_cast<double>(p.x) - c.x, static_cast<double>(p.y) - c.y);
    for (const Triangle& t : mesh.triangles)
      for (const std::uint32_t i : {t.a, t.b, t.c}) piece.triangles.push_back(static_cast<int>(i));
    debris.shape.push_back(std::move(piece));
  }
  bodies_.push_back(std::move(debris));
}

void Physics::step(double seconds) {
  world_->Step(static_cast<float>(seconds), 8, 3);
  std::erase_if(bodies_, [&](const DynamicBody& d) {
    if (d.body->GetPosition().y > -8.0f) return false;  // 8 m below the world's floor: gone
    world_->DestroyBody(d.body);
    return true;
  });
}

std::size_t Physics::remove_buried(const std::function<bool(Point64)>& covered) {
  return std::erase_if(bodies_, [&](const DynamicBody& d) {
    if (d.kind == BodyKind::kDebris || !covered(centre(d))) return false;
    world_->DestroyBody(d.body);
    return true;
  });
}

void Physics::remove_debris() {
  std::erase_if(bodies_, [&](const DynamicBody& d) {
    if (d.kind != BodyKind::kDebris) return false;
    world_->DestroyBody(d.body);
    return true;
  });
}

}  // namespace edgeland::play
