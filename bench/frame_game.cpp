// The frame-based game of frame_game.hpp: the world, the bodies, the edits of each frame, and
// the two sides that take them.
#include "frame_game.hpp"

#include <algorithm>
#include <optional>

#include "edgeland/box2d/terrain.hpp"
#include "edgeland/game/render_meshes.hpp"
#include "edgeland/kernel/shapes.hpp"
#include "edgeland/kernel/splitmix64.hpp"
#include "game_common.hpp"
#include "pixel_terrain.hpp"

namespace edgeland::bench {
namespace {

constexpr Material kBedrock = 1, kRock = 2, kDirt = 3, kBrick = 4;

class Random {
 public:
  explicit Random(std::uint64_t seed) : gen_(seed) {}
  std::int64_t in(std::int64_t lo, std::int64_t hi) {  // [lo, hi]
    return lo + static_cast<std::int64_t>(gen_.next() % static_cast<std::uint64_t>(hi - lo + 1));
  }

 private:
  SplitMix64 gen_;
};

// The ground's top: hills of period size / 4 between 7/16 and 9/16 of the height.
Polygon ground(std::int64_t size) {
  Polygon rock{{0, 0}, {size, 0}};
  const std::int64_t steps = 32, base = size * 7 / 16, amplitude = size / 8;
  for (std::int64_t i = steps; i >= 0; --i) {
    const std::int64_t phase = (i * 4) % steps;
    const std::int64_t up = phase < steps / 2 ? phase : steps - phase;
    rock.push_back({size * i / steps, base + amplitude * up * 2 / steps});
  }
  return rock;
}

// Rock hills with dirt on top over a bedrock floor, and a few caves.
Landscape game_world(std::int64_t size) {
  Landscape world({{0, 0}, {size, size}});
  world.fill(PolygonSet{ground(size)}, kRock);
  world.replace(PolygonSet{box_shape({{0, size * 15 / 32}, {size, size}})}, kRock, kDirt);
  world.fill(PolygonSet{box_shape({{0, 0}, {size, size / 16}})}, kBedrock);
  for (std::int64_t k = 1; k < 8; ++k)
    world.carve(PolygonSet{circle({size * k / 8, size * (4 + k % 3) / 16}, size / 40)});
  return world;
}

// The landscape's squares as a bitmap: every polygon painted with its material.
BitmapWorld as_bitmap(const Landscape& land) {
  BitmapWorld bitmap(land.world(), kEmpty);
  land.polygons_in(land.world(), [&](const PolygonView& v) {
    bitmap.paint(PolygonSet{*v.polygon}, v.material);
    return true;
  });
  return bitmap;
}

GameOptions game_options() {
  GameOptions o;
  o.surface.materials.set_anchored(kBedrock);
  o.surface.border_wall = true;
  return o;
}

box2d::TerrainOptions terrain_options() {
  box2d::TerrainOptions o;
  o.units_per_metre = kUnitsPerMetre;
  return o;
}

void step(b2World& world) { world.Step(1.0f / 60.0f, 8, 3); }

struct Body {
  b2Body* body = nullptr;
  bool debris = false;
};

// The edgeland side: the game driver, the terrain and debris it hands Box2D, and the bodies.
// Edits and colliders are timed apart; "islands" is the debris bodies made.
class EdgelandGame {
 public:
  explicit EdgelandGame(const Landscape& start)
      : game_(start, game_options()), terrain_(world_, game_, terrain_options()) {}

  void frame(const std::vector<FrameEdit>& edits, std::array<double, kFrameStageCount>& t,
             FrameGameRun& run) {
    batch_.clear();
    for (const FrameEdit& e : edits) {
      ValidSet shape(PolygonSet{e.shape}, Operand::kClip);
      batch_.push_back(e.kind == FrameEdit::Kind::kCarve
                           ? edgeland::Edit::carve(std::move(shape))
                           : edgeland::Edit::fill(std::move(shape), e.material));
    }
    ThreadClock clock;
    const GameUpdate u = game_.apply(batch_);
    t[kFrameEdits] += clock.lap();
    terrain_.apply(u);
    t[kFrameColliders] += clock.lap();
    for (const Debris& d : u.debris)
      bodies_.push_back({box2d::make_debris_body(world_, d, units()), true});
    t[kFrameIslands] += clock.lap();
    benchmark::DoNotOptimize(u.meshes);
    note(u, run);
  }

  b2World& world() { return world_; }
  const Landscape& land() const { return game_.landscape(); }
  const GameDriver& game() const { return game_; }
  std::vector<Body>& bodies() { return bodies_; }
  const std::vector<Body>& bodies() const { return bodies_; }
  const box2d::Terrain& terrain() const { return terrain_; }
  const EngineUnits& units() const { return terrain_.units(); }

 private:
  void note(const GameUpdate& u, FrameGameRun& run) {
    run.detached += u.debris.size();
    for (const Debris& d : u.debris) {
      run.debris_fixtures_max = std::max(run.debris_fixtures_max, d.pieces.size());
      std::size_t polygons = 0;
      for (const Debris::Region& r : d.regions) polygons += r.polygons.size();
      run.debris_polygons_max = std::max(run.debris_polygons_max, polygons);
    }
  }

  b2World world_{b2Vec2(0, -10)};
  GameDriver game_;
  box2d::Terrain terrain_;
  std::vector<Body> bodies_;
  std::vector<edgeland::Edit> batch_;
};

class PixelGame {
 public:
  explicit PixelGame(const BitmapWorld& start)
      : bitmap_(start), terrain_(world_, bitmap_, options()) {}

  void edit(const FrameEdit& e, std::array<double, kFrameStageCount>& t) {
    const PolygonSet shape{e.shape};
    ThreadClock clock;
    bitmap_.paint(shape, e.kind == FrameEdit::Kind::kCarve ? kEmpty : e.material);
    t[kFramePaint] += clock.lap();
    const auto& traced = terrain_.trace(bitmap_, *bounding_box(shape));
    t[kFrameTrace] += clock.lap();
    terrain_.rebuild(traced);
    t[kFrameRebuild] += clock.lap();
  }

  b2World& world() { return world_; }
  std::size_t fixtures() const { return terrain_.fixture_count(); }

 private:
  static PixelTerrain::Options options() {
    PixelTerrain::Options o;
    o.solid.fill(true);
    o.solid[kEmpty.value()] = false;
    o.units_per_metre = kUnitsPerMetre;
    return o;
  }

  b2World world_{b2Vec2(0, -10)};
  BitmapWorld bitmap_;
  PixelTerrain terrain_;
};

// The game: bodies, the edits chosen near them, burying, and the frames.
class FrameGame {
 public:
  explicit FrameGame(const FrameGameOptions& options)
      : options_(options),
        random_(options.seed),
        start_(game_world(options.size)),
        edgeland_(start_),
        pixel_(as_bitmap(start_)) {
    drop_bodies(options_.bodies);
    for (int i = 0; i < 120; ++i) step(edgeland_.world());  // the bodies land
  }

  FrameGameRun play(bool edgeland_first) {
    FrameGameRun run;
    for (auto& s : run.seconds) s.reserve(options_.frames);
    for (std::size_t f = 0; f < options_.frames; ++f) frame(edgeland_first, run);
    run.terrain_fixtures = edgeland_.terrain().fixture_count();
    run.pixel_fixtures = pixel_.fixtures();
    run.state_hash = edgeland_.land().state_hash();
    run.landscape_ok = edgeland_.land().check().ok();
    return run;
  }

 private:
  void frame(bool edgeland_first, FrameGameRun& run) {
    std::array<double, kFrameStageCount> t{};
    const std::int64_t count = random_.in(1, 3);
    std::vector<FrameEdit> edits;
    for (std::int64_t k = 0; k < count; ++k) edits.push_back(next_edit());
    if (edgeland_first) edgeland_.frame(edits, t, run);
    for (const FrameEdit& e : edits) pixel_.edit(e, t);
    if (!edgeland_first) edgeland_.frame(edits, t, run);
    run.edits += edits.size();
    bury(run);
    ThreadClock clock;
    step(edgeland_.world());
    t[kFrameEdgelandStep] = clock.lap();
    step(pixel_.world());
    t[kFramePixelStep] = clock.lap();
    t[kFrameEdgeland] = t[kFrameEdits] + t[kFrameColliders] + t[kFrameIslands] + t[kFrameMeshes];
    t[kFramePixel] = t[kFramePaint] + t[kFrameTrace] + t[kFrameRebuild];
    for (std::size_t s = 0; s < kFrameStageCount; ++s) run.seconds[s].push_back(t[s]);
    drop_bodies(options_.bodies - balls_and_boxes());
  }

  Point64 centre(const b2Body* body) const {
    const b2Vec2 p = body->GetPosition();
    return edgeland_.units().to_world({p.x, p.y});
  }

  // An explosion (circle or n-gon), a tunnel or a builder's fill near a random ball or box.
  FrameEdit next_edit() {
    std::vector<Body>& bodies = edgeland_.bodies();
    Point64 c = centre(bodies[static_cast<std::size_t>(random_.in(0, bodies.size() - 1))].body);
    c = {std::clamp<std::int64_t>(c.x, 0, options_.size),
         std::clamp<std::int64_t>(c.y, 0, options_.size)};
    const std::int64_t roll = random_.in(0, 99);
    const Point64 below{c.x + random_.in(-40, 40), c.y - random_.in(0, 60)};
    if (roll < 35) return {FrameEdit::Kind::kCarve, circle(below, random_.in(8, 40)), kEmpty};
    if (roll < 50)
      return {
          FrameEdit::Kind::kCarve,
          regular_polygon(below, random_.in(8, 48), random_.in(5, 12), {random_.in(0, 99), 100}),
          kEmpty};
    if (roll < 70) {
      const Point64 to{below.x + random_.in(-80, 80), below.y + random_.in(-30, 30)};
      return {FrameEdit::Kind::kCarve, capsule(below, to, random_.in(6, 16)), kEmpty};
    }
    const Point64 beside{c.x + random_.in(-60, 60), c.y - random_.in(0, 40)};
    if (roll < 85) return {FrameEdit::Kind::kFill, circle(beside, random_.in(6, 24)), kBrick};
    return {FrameEdit::Kind::kFill,
            regular_polygon(beside, random_.in(8, 32), random_.in(3, 8), {random_.in(0, 99), 100}),
            kDirt};
  }

  // The bodies the frame's fills buried (debris too) leave the play.
  void bury(FrameGameRun& run) {
    std::vector<Body>& bodies = edgeland_.bodies();
    for (Body& b : bodies) {
      if (!edgeland_.game().buried(box_of(b.body))) continue;
      edgeland_.world().DestroyBody(b.body);
      b.body = nullptr;
      ++run.buried;
    }
    std::erase_if(bodies, [](const Body& b) { return b.body == nullptr; });
  }

  Box64 box_of(const b2Body* body) const {
    b2AABB a = body->GetFixtureList()->GetAABB(0);
    for (const b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext()) a.Combine(f->GetAABB(0));
    const Point64 lo = edgeland_.units().to_world({a.lowerBound.x, a.lowerBound.y});
    const Point64 hi = edgeland_.units().to_world({a.upperBound.x, a.upperBound.y});
    return {{lo.x - 1, lo.y - 1}, {hi.x + 1, hi.y + 1}};
  }

  int balls_and_boxes() const {
    const std::vector<Body>& bodies = edgeland_.bodies();
    return static_cast<int>(
        std::count_if(bodies.begin(), bodies.end(), [](const Body& b) { return !b.debris; }));
  }

  // Balls and boxes of half a metre dropped from above the hills.
  void drop_bodies(int count) {
    for (int i = 0; i < count; ++i) {
      const std::int64_t s = options_.size;
      b2BodyDef def;
      def.type = b2_dynamicBody;
      def.position = box2d::to_b2(
          edgeland_.units(), {random_.in(s / 20, s - s / 20), s * 3 / 4 + random_.in(0, s / 8)});
      b2Body* body = edgeland_.world().CreateBody(&def);
      b2CircleShape ball;
      ball.m_radius = 0.5f;
      b2PolygonShape box;
      box.SetAsBox(0.5f, 0.5f);
      b2FixtureDef fixture;
      fixture.shape = i % 2 ? static_cast<b2Shape*>(&ball) : static_cast<b2Shape*>(&box);
      fixture.density = 1;
      fixture.friction = 0.5f;
      body->CreateFixture(&fixture);
      edgeland_.bodies().push_back({body, false});
    }
  }

  FrameGameOptions options_;
  Random random_;
  Landscape start_;
  EdgelandGame edgeland_;
  PixelGame pixel_;
};

}  // namespace

FrameGameRun play_frame_game(const FrameGameOptions& options, bool edgeland_first) {
  FrameGame game(options);
  return game.play(edgeland_first);
}

}  // namespace edgeland::bench
