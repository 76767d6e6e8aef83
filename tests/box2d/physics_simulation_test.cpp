// The Box2D adapter in a running simulation (issue 26): a layered world, 200 balls and boxes
// resting and rolling on it, thousands of carves and fills near them with the terrain updated
// from every change set, debris islands detached and falling; and a box sliding over cell lines.
// Headless, deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include "edgeland/box2d/terrain.hpp"
#include "physics_scenario.hpp"

namespace edgeland::test {
namespace {

constexpr std::int64_t kSize = 4096;
constexpr float kUnitsPerMetre = 32;  // the world is 128 m wide

// One fixture of the terrain as plain numbers: its chain's vertices and ghosts.
struct FixtureShape {
  std::vector<std::pair<float, float>> points;
  std::pair<float, float> prev, next;
  bool loop = false;
  std::uintptr_t material = 0;
  friend auto operator<=>(const FixtureShape&, const FixtureShape&) = default;
};

std::vector<FixtureShape> fixtures_of(const box2d::Terrain& terrain) {
  std::vector<FixtureShape> out;
  for (b2Body* body : terrain.bodies())
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

// The scenario of `edgeland demo --physics` (demo/physics): 200 balls and boxes on a
// layered world with hills, 3 blasts or fills near them per frame for 1,200 frames.
TEST(PhysicsSimulation, BodiesStayOutOfSolidWhileTheTerrainChangesUnderThem) {
  box2d::PhysicsScenario scenario;
  const box2d::PhysicsScene& scene = scenario.scene();
  scenario.settle(120);  // let them land
  for (int frame = 0; frame < 1200; ++frame) {
    scenario.frame();
    const std::vector<Point64> inside = scene.centres_in_solid();
    ASSERT_TRUE(inside.empty()) << "frame " << frame
                                << ": a body's centre is in solid material at (" << inside.front().x
                                << " " << inside.front().y << ")";
    const std::vector<Point64> outside = scene.centres_outside_world();
    ASSERT_TRUE(outside.empty()) << "frame " << frame << ": a body left the world at ("
                                 << outside.front().x << " " << outside.front().y << ")";
  }
  EXPECT_GE(scenario.stats().edits, 3600);
  EXPECT_GT(scene.stats().detached, 0);
  // The debris fell: most debris bodies still in play are below where they were made.
  std::size_t debris = 0, fell = 0;
  for (const box2d::SceneBody& b : scene.bodies()) {
    const bool is_debris = b.kind == box2d::BodyKind::kDebris;
    debris += is_debris;
    fell += is_debris && b.body->GetPosition().y < b.start_y - 0.1f;
  }
  EXPECT_GT(debris, 0u);
  EXPECT_GT(2 * fell, debris);
  // The fixtures kept from change sets equal those of a terrain built from scratch.
  b2World fresh_world(b2Vec2(0, -10));
  GameOptions options = box2d::PhysicsScenario::game_options();
  options.debris = false;
  const GameDriver fresh_game(scene.land(), options);
  const box2d::Terrain fresh(
      fresh_world, fresh_game,
      box2d::PhysicsScenario::terrain_options(box2d::PhysicsScenarioOptions{}));
  EXPECT_EQ(fixtures_of(scene.terrain()), fixtures_of(fresh));
  // A static body per region with chains: none left empty by the updates, none missing.
  EXPECT_EQ(scene.terrain().bodies().size(), fresh.bodies().size());
  for (const b2Body* body : scene.terrain().bodies()) EXPECT_NE(body->GetFixtureList(), nullptr);
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
  [[maybe_unused]] const auto terrain = add_terrain(world, land);
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
  out.cell_lines_crossed = static_cast<int>((box->GetPosition().x - start_x) * kUnitsPerMetre / 64);
  return out;
}

TEST(PhysicsSimulation, ABoxSlidesAcrossCellLinesWithoutBumps) {
  const Slide slide = slide_a_box([](b2World& world, const Landscape& land) {
    box2d::TerrainOptions options;
    options.units_per_metre = kUnitsPerMetre;
    options.friction.fill(0);
    const GameDriver game(land);  // the terrain reads its chains once
    return std::make_unique<box2d::Terrain>(world, game, options);
  });
  EXPECT_GE(slide.cell_lines_crossed, 6);
  EXPECT_LT(slide.largest_vy, 1e-3f);   // measured: 2e-6
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

// Issue 36, point 7: in a world cornered at (10^6, 10^6) the debris body of an island appears
// where the island was, in the terrain's own units (the corner is Box2D's origin).
TEST(PhysicsSimulation, DebrisOfAFarWorldLandsWhereItsIslandWas) {
  const Point64 corner{1'000'000, 1'000'000};
  Landscape land({corner, {corner.x + 4096, corner.y + 4096}}, kEmpty);
  land.fill(PolygonSet{{{corner.x, corner.y},
                        {corner.x + 4096, corner.y},
                        {corner.x + 4096, corner.y + 1000},
                        {corner.x, corner.y + 1000}}},
            1);
  GameDriver game(std::move(land));
  b2World world(b2Vec2(0, -10));
  box2d::TerrainOptions options;
  options.units_per_metre = kUnitsPerMetre;
  box2d::Terrain terrain(world, game, options);
  EXPECT_EQ(terrain.units().origin, corner);
  // A moat around a 180 x 180 block centred 2048 x 768 units from the corner: 64 m, 24 m.
  const std::int64_t x = corner.x + 1948, y = corner.y + 668;
  const PolygonSet moat{
      {{x - 10, y - 10}, {x + 190, y - 10}, {x + 190, y}, {x - 10, y}},
      {{x - 10, y + 180}, {x + 190, y + 180}, {x + 190, y + 190}, {x - 10, y + 190}},
      {{x - 10, y}, {x, y}, {x, y + 180}, {x - 10, y + 180}},
      {{x + 180, y}, {x + 190, y}, {x + 190, y + 180}, {x + 180, y + 180}}};
  const GameUpdate u = game.apply(Edit::carve(ValidSet(moat)));
  terrain.apply(u);
  ASSERT_EQ(u.debris.size(), 1u);
  const b2Body* body = box2d::make_debris_body(world, u.debris.front(), terrain.units());
  EXPECT_FLOAT_EQ(body->GetPosition().x, 2038.0f / kUnitsPerMetre);
  EXPECT_FLOAT_EQ(body->GetPosition().y, 758.0f / kUnitsPerMetre);
  EXPECT_NEAR(body->GetMass(), 180.0f * 180.0f / (kUnitsPerMetre * kUnitsPerMetre), 1e-3f);

  // An explicit origin (0, 0) is taken as given, not as "unset": the same debris then lies at the
  // landscape's own coordinates.
  b2World far_world(b2Vec2(0, -10));
  box2d::TerrainOptions at_zero = options;
  at_zero.origin = Point64{0, 0};
  box2d::Terrain zero_terrain(far_world, game, at_zero);
  EXPECT_EQ(zero_terrain.units().origin, (Point64{0, 0}));
  const b2Body* far_body =
      box2d::make_debris_body(far_world, u.debris.front(), zero_terrain.units());
  EXPECT_FLOAT_EQ(far_body->GetPosition().x, static_cast<float>(x + 90) / kUnitsPerMetre);
  EXPECT_FLOAT_EQ(far_body->GetPosition().y, static_cast<float>(y + 90) / kUnitsPerMetre);
}

// A world reaching past 2^24 units from the origin is refused, naming the corner.
TEST(PhysicsSimulation, AWorldFloatsCannotHoldIsRefused) {
  const std::int64_t far = std::int64_t{1} << 25;
  GameDriver game(Landscape({{0, 0}, {far, 1024}}, kEmpty));
  b2World world(b2Vec2(0, -10));
  try {
    box2d::Terrain terrain(world, game);
    FAIL() << "a world 2^25 units wide was taken";
  } catch (const box2d::OutOfEngineRange& e) {
    EXPECT_EQ(e.point.x, far);
    EXPECT_EQ(e.origin, (Point64{0, 0}));
    EXPECT_EQ(e.limit, box2d::kMaxEngineOffset);
  }
  // The same world with its origin in the middle fits.
  box2d::TerrainOptions middle;
  middle.origin = Point64{far / 2, 0};
  EXPECT_NO_THROW(box2d::Terrain(world, game, middle));
}

}  // namespace
}  // namespace edgeland::test
