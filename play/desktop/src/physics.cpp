#include "physics.hpp"

#include <algorithm>
#include <cmath>

namespace edgeland::play {

Physics::Physics(const Box64& world, double units_per_metre, std::function<bool(Material)> solid)
    : box_(world),
      k_(units_per_metre),
      solid_(std::move(solid)),
      world_(std::make_unique<b2World>(b2Vec2(0.0f, -10.0f))) {}

b2Vec2 Physics::metres(Point64 p) const {
  return {static_cast<float>(static_cast<double>(p.x - box_.min.x) / k_),
          static_cast<float>(static_cast<double>(p.y - box_.min.y) / k_)};
}

double Physics::world_x(float metres_x) const {
  return static_cast<double>(box_.min.x) + metres_x * k_;
}
double Physics::world_y(float metres_y) const {
  return static_cast<double>(box_.min.y) + metres_y * k_;
}

Point64 Physics::centre(const DynamicBody& body) const {
  const b2Vec2 p = body.body->GetPosition();
  return {std::llround(world_x(p.x)), std::llround(world_y(p.y))};
}

void Physics::add_terrain(PolygonId id, Material material, const Polygon& polygon) {
  if (!solid_(material)) return;
  std::vector<b2Vec2> points;
  points.reserve(polygon.size());
  for (const Point64& p : polygon) points.push_back(metres(p));
  b2BodyDef def;
  b2Body* body = world_->CreateBody(&def);
  b2ChainShape chain;
  chain.CreateLoop(points.data(), static_cast<int32>(points.size()));
  b2FixtureDef fixture;
  fixture.shape = &chain;
  fixture.friction = 0.6f;
  body->CreateFixture(&fixture);
  terrain_[id] = body;
}

void Physics::remove_terrain(PolygonId id) {
  const auto it = terrain_.find(id);
  if (it == terrain_.end()) return;
  world_->DestroyBody(it->second);
  terrain_.erase(it);
}

void Physics::apply(const ChangeSet& changes) {
  for (const PolygonId id : changes.removed) remove_terrain(id);
  for (const ChangeSet::Added& a : changes.added) add_terrain(a.id, a.material, a.polygon);
}

void Physics::reset(const Landscape& landscape) {
  for (const auto& [id, body] : terrain_) world_->DestroyBody(body);
  terrain_.clear();
  landscape.polygons_in(landscape.world(), [&](const PolygonView& v) {
    add_terrain(v.id, v.material, *v.polygon);
    return true;
  });
}

void Physics::drop_ball(Point64 at, double radius) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = metres(at);
  b2Body* body = world_->CreateBody(&def);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(radius / k_);
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
  box.SetAsBox(static_cast<float>(half / k_), static_cast<float>(half / k_));
  b2FixtureDef fixture;
  fixture.shape = &box;
  fixture.density = 1;
  fixture.friction = 0.5f;
  body->CreateFixture(&fixture);
  bodies_.push_back({body, BodyKind::kBox, half});
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
    if (!covered(centre(d))) return false;
    world_->DestroyBody(d.body);
    return true;
  });
}

}  // namespace edgeland::play
