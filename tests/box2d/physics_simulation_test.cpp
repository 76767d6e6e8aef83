// The Box2D adapter in a running simulation (issue 26): a layered world, 200 balls and boxes
// resting and rolling on it, thousands of carves and fills near them with the terrain updated
// from every change set, debris islands detached and falling. Headless, deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include "edgeland/box2d/terrain.hpp"
#include "game_worlds.hpp"

namespace edgeland::test {
namespace {

constexpr std::int64_t kSize = 4096;
constexpr double kUnitsPerMetre = 32;  // the world is 128 m wide

// One fixture of the terrain as plain numbers: its chain's vertices and ghosts.
struct FixtureShape {
  std::vector<std::pair<float, float>> points;
  std::pair<float, float> prev, next;
  bool loop = false;
  std::uintptr_t material = 0;
  friend auto operator<=>(const FixtureShape&, const FixtureShape&) = default;
};

std::vector<FixtureShape> fixtures_of(b2Body* body) {
  std::vector<FixtureShape> out;
  for (b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext()) {
    const auto* chain = static_cast<const b2ChainShape*>(f->GetShape());
    FixtureShape s;
    for (int32 i = 0; i < chain->m_count; ++i)
      s.points.emplace_back(chain->m_vertices[i].x, chain->m_vertices[i].y);
    s.prev = {chain->m_prevVertex.x, chain->m_prevVertex.y};
    s.next = {chain->m_nextVertex.x, chain->m_nextVertex.y};
    s.loop = chain->m_count > 1 && chain->m_vertices[0] == chain->m_vertices[chain->m_count - 1];
    s.material = f->GetUserData().pointer;
    out.push_back(std::move(s));
  }
  std::sort(out.begin(), out.end());
  return out;
}

struct Body {
  b2Body* body;
  bool debris;
  float start_y = 0;  // where a debris body was made
};

class Simulation {
 public:
  explicit Simulation(std::uint64_t seed)
      : rng_(seed), land_(layered_world(kSize)), world_(b2Vec2(0, -10)), terrain_(make_terrain()),
        islands_(land_, materials()) {}

  static PhysicsMaterials materials() {
    PhysicsMaterials m;
    m.anchored[3] = true;  // bedrock
    return m;
  }

  void drop_bodies(int count) {
    for (int i = 0; i < count; ++i) {
      b2BodyDef def;
      def.type = b2_dynamicBody;
      const Point64 at{rng_.in(200, kSize - 200), kSize * 5 / 8 + rng_.in(300, 700)};
      def.position = box2d::to_b2(terrain_.units(), at);
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
      bodies_.push_back({body, false});
    }
  }

  // A blast around a random body, or a fill beside or below it; bodies buried by the fill are
  // replaced by new ones dropped from the sky, so about 200 are always in play.
  void edit_near_a_body() {
    const Body& target = bodies_[static_cast<std::size_t>(rng_.in(0, bodies_.size() - 1))];
    const Point64 c = centre(target.body);
    if (rng_.in(0, 3) == 0) {
      const Point64 at{c.x + rng_.in(-120, 120), c.y - rng_.in(40, 120)};
      const PolygonSet shape{blast(rng_, at, rng_.in(8, 32))};
      bury_bodies_under(shape);
      apply(land_.fill(shape, static_cast<Material>(rng_.in(1, 2))));
      drop_bodies(200 - balls_and_boxes());
    } else {
      const Point64 at{c.x + rng_.in(-60, 60), c.y + rng_.in(-80, 20)};
      apply(land_.carve(PolygonSet{blast(rng_, at, rng_.in(8, 48))}));
    }
  }

  int balls_and_boxes() const {
    return static_cast<int>(std::count_if(bodies_.begin(), bodies_.end(),
                                          [](const Body& b) { return !b.debris; }));
  }

  // Every tracker sees every edit, the detaches too. A detach can re-cut the cells of another
  // island found by the same edit: that one is then stale, and the tracker reports it again.
  void apply(const ChangeSet& changes) {
    ++edits_;
    terrain_.update(land_, changes);
    std::vector<Island> pending = islands_.update(land_, changes);
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
      for (Island& again : islands_.update(land_, detached.changes)) pending.push_back(std::move(again));
      b2Body* debris = box2d::make_debris_body(world_, detached, terrain_.units());
      bodies_.push_back({debris, true, debris->GetPosition().y});
      ++detached_;
    }
  }

  void step() { world_.Step(1.0f / 60.0f, 8, 3); }

  Point64 centre(const b2Body* body) const {
    const b2Vec2 p = body->GetPosition();
    return terrain_.units().to_world({p.x, p.y});
  }

  // The bodies (not debris) whose centre is in solid material.
  std::vector<Point64> centres_in_solid() const {
    std::vector<Point64> out;
    for (const Body& b : bodies_) {
      if (b.debris) continue;
      const Point64 c = centre(b.body);
      if (materials().is_solid(land_.material_at(c))) out.push_back(c);
    }
    return out;
  }

  // The centres of bodies outside the world's box.
  std::vector<Point64> centres_outside_world() const {
    std::vector<Point64> out;
    for (const Body& b : bodies_) {
      const Point64 c = centre(b.body);
      if (!land_.world().contains(c)) out.push_back(c);
    }
    return out;
  }

  const Landscape& land() const { return land_; }
  b2World& world() { return world_; }
  const box2d::Terrain& terrain() const { return terrain_; }
  int edits() const { return edits_; }
  int detached() const { return detached_; }
  int buried() const { return buried_; }
  const std::vector<Body>& bodies() const { return bodies_; }

 private:
  box2d::Terrain make_terrain() {
    box2d::TerrainOptions options;
    options.surface.materials = materials();
    options.surface.border_wall = true;  // nothing leaves the world
    options.units.units_per_engine_unit = kUnitsPerMetre;
    return box2d::Terrain(world_, land_, options);
  }

  // The body's box in landscape units, rounded outwards.
  Box64 box_of(b2Body* body) const {
    const b2AABB a = body->GetFixtureList()->GetAABB(0);
    const Point64 lo = terrain_.units().to_world({a.lowerBound.x, a.lowerBound.y});
    const Point64 hi = terrain_.units().to_world({a.upperBound.x, a.upperBound.y});
    return {{lo.x - 1, lo.y - 1}, {hi.x + 1, hi.y + 1}};
  }

  // A fill buries the bodies it overlaps, debris included (the game put solid where they are):
  // they leave the simulation, the one exception to "no centre in solid".
  void bury_bodies_under(const PolygonSet& shape) {
    Landscape probe({{0, 0}, {kSize, kSize}});
    probe.fill(shape, 1);
    for (Body& b : bodies_) {
      if (probe.overlaps(box_of(b.body)).empty()) continue;
      world_.DestroyBody(b.body);
      b.body = nullptr;
      ++buried_;
    }
    bodies_.erase(std::remove_if(bodies_.begin(), bodies_.end(),
                                 [](const Body& b) { return b.body == nullptr; }),
                  bodies_.end());
  }

  SplitMix rng_;
  Landscape land_;
  b2World world_;
  box2d::Terrain terrain_;
  IslandTracker islands_;
  std::vector<Body> bodies_;
  int edits_ = 0, detached_ = 0, buried_ = 0;
};

TEST(PhysicsSimulation, BodiesStayOutOfSolidWhileTheTerrainChangesUnderThem) {
  Simulation sim(2026);
  sim.drop_bodies(200);
  for (int frame = 0; frame < 120; ++frame) sim.step();  // let them land
  for (int frame = 0; frame < 1200; ++frame) {
    for (int k = 0; k < 3; ++k) sim.edit_near_a_body();
    sim.step();
    const std::vector<Point64> inside = sim.centres_in_solid();
    ASSERT_TRUE(inside.empty()) << "frame " << frame << ": a body's centre is in solid material at ("
                                << inside.front().x << " " << inside.front().y << ")";
    const std::vector<Point64> outside = sim.centres_outside_world();
    ASSERT_TRUE(outside.empty()) << "frame " << frame << ": a body left the world at ("
                                 << outside.front().x << " " << outside.front().y << ")";
  }
  EXPECT_GE(sim.edits(), 3600);
  EXPECT_GT(sim.detached(), 0);
  // The debris fell: most debris bodies still in play are below where they were made.
  std::size_t debris = 0, fell = 0;
  for (const Body& b : sim.bodies()) {
    debris += b.debris;
    fell += b.debris && b.body->GetPosition().y < b.start_y - 0.1f;
  }
  EXPECT_GT(debris, 0u);
  EXPECT_GT(2 * fell, debris);
  // The fixtures kept from change sets equal those of a terrain built from scratch.
  b2World fresh_world(b2Vec2(0, -10));
  box2d::TerrainOptions options;
  options.surface.materials = Simulation::materials();
  options.surface.border_wall = true;
  options.units.units_per_engine_unit = kUnitsPerMetre;
  const box2d::Terrain fresh(fresh_world, sim.land(), options);
  EXPECT_EQ(fixtures_of(sim.terrain().body()), fixtures_of(fresh.body()));
}

// A box sliding without friction along a flat floor cut by a cell line every 64 units (2 m): its
// velocity stays what it was, with no vertical bump where it passes a joint between two cells'
// chains (Box2D's "ghost collisions", which the ghost vertices are there to prevent).
struct Slide {
  float largest_vy = 0, largest_dvx = 0;
  int cell_lines_crossed = 0;
};

// add_terrain(world, land) builds the floor's fixtures and returns what must outlive the steps
// (and die before the world).
template <class AddTerrain>
Slide slide_a_box(AddTerrain add_terrain) {
  LandscapeConfig grid;
  grid.grid_depth = 6;  // 64 x 64 cells of 64 units
  Landscape land({{0, 0}, {kSize, kSize}}, kEmpty, grid);
  land.fill(PolygonSet{{{0, 0}, {kSize, 0}, {kSize, 1000}, {0, 1000}}}, 1);
  b2World world(b2Vec2(0, -10));
  const auto terrain = add_terrain(world, land);
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position.Set(200 / kUnitsPerMetre, 1000 / kUnitsPerMetre + 0.5f);
  def.linearVelocity.Set(5, 0);
  b2Body* box = world.CreateBody(&def);
  b2PolygonShape shape;
  shape.SetAsBox(0.5f, 0.5f);
  b2FixtureDef fixture;
  fixture.shape = &shape;
  fixture.density = 1;
  fixture.friction = 0;
  box->CreateFixture(&fixture);
  Slide out;
  const float start_x = box->GetPosition().x;
  for (int i = 0; i < 180; ++i) {
    world.Step(1.0f / 60.0f, 8, 3);
    out.largest_vy = std::max(out.largest_vy, std::abs(box->GetLinearVelocity().y));
    out.largest_dvx = std::max(out.largest_dvx, std::abs(box->GetLinearVelocity().x - 5));
  }
  out.cell_lines_crossed =
      static_cast<int>((box->GetPosition().x - start_x) * kUnitsPerMetre / 64);
  return out;
}

TEST(PhysicsSimulation, ABoxSlidesAcrossCellLinesWithoutBumps) {
  const Slide slide = slide_a_box([](b2World& world, const Landscape& land) {
    box2d::TerrainOptions options;
    options.units.units_per_engine_unit = kUnitsPerMetre;
    options.friction.fill(0);
    return std::make_unique<box2d::Terrain>(world, land, options);
  });
  EXPECT_GE(slide.cell_lines_crossed, 6);
  EXPECT_LT(slide.largest_vy, 1e-3f);  // measured: 2e-6
  EXPECT_LT(slide.largest_dvx, 1e-3f);  // measured: 0
}

// The same floor made of each cell's polygons as closed loops, as a game without the surface
// chains would: the box catches on the joints. (This shows the test above can fail.)
TEST(PhysicsSimulation, PerPolygonLoopsMakeTheSameBoxBump) {
  const Slide slide = slide_a_box([](b2World& world, const Landscape& land) {
    b2BodyDef def;
    b2Body* body = world.CreateBody(&def);
    const EngineUnits units{land.world().min, kUnitsPerMetre};
    land.polygons_in(land.world(), [&](const PolygonView& v) {
      std::vector<b2Vec2> points;
      for (const Point64& p : *v.polygon) points.push_back(box2d::to_b2(units, p));
      b2ChainShape loop;
      loop.CreateLoop(points.data(), static_cast<int32>(points.size()));
      b2FixtureDef fixture;
      fixture.shape = &loop;
      fixture.friction = 0;
      body->CreateFixture(&fixture);
      return true;
    });
    return 0;
  });
  EXPECT_GT(std::max(slide.largest_vy, slide.largest_dvx), 1e-3f);  // measured: vy 3.6e-3
}

}  // namespace
}  // namespace edgeland::test
