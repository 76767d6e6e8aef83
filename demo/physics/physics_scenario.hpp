#pragma once
// The seeded physics scenario of tests/box2d and `edgeland demo --physics` (one scenario, so the
// demo shows what the test checks), on the demos' one Box2D scene (physics_scene.hpp): a layered
// world with hills (bedrock, rock, dirt), 200 balls and boxes resting and rolling on it, and a
// stream of blasts and fills near them. Each frame's edits go to the game driver as one batch;
// its update goes to the scene (the terrain's fixtures, a body per debris), and the bodies its
// fills buried leave the play. Deterministic: a seeded generator, a fixed step.
#include <cstdint>

#include "edgeland/kernel/splitmix64.hpp"
#include "physics_scene.hpp"

namespace edgeland::box2d {

struct PhysicsScenarioOptions {
  std::uint64_t seed = 2026;
  std::int64_t size = 4096;     // the world is size x size units
  double units_per_metre = 32;  // 4096 units = 128 m
  int bodies = 200;             // balls and boxes in play (buried ones are replaced)
  int edits_per_frame = 3;
};

// The scenario's part of the work (the scene's own is PhysicsScene::stats()).
struct ScenarioStats {
  int frames = 0, settled = 0;  // steps with edits, steps without
  int edits = 0, buried = 0;
  double game_seconds = 0;  // GameDriver::apply
};

class PhysicsScenario {
 public:
  explicit PhysicsScenario(const PhysicsScenarioOptions& options = {});
  PhysicsScenario(const PhysicsScenario&) = delete;
  PhysicsScenario& operator=(const PhysicsScenario&) = delete;

  // Steps without edits (the bodies land).
  void settle(int frames);
  // `edits_per_frame` edits near random bodies as one batch, the update applied, the buried
  // bodies replaced, then one step of 1/60 s.
  void frame();

  static PhysicsMaterials materials();  // bedrock (1) anchored
  static GameOptions game_options();
  static TerrainOptions terrain_options(const PhysicsScenarioOptions& options);

  const PhysicsScene& scene() const { return scene_; }
  const Landscape& land() const { return game_.landscape(); }
  const ScenarioStats& stats() const { return stats_; }

 private:
  class Random {
   public:
    explicit Random(std::uint64_t seed) : source_(seed) {}
    std::int64_t in(std::int64_t lo, std::int64_t hi);  // [lo, hi]

   private:
    SplitMix64 source_;
  };

  void drop_bodies(int count);
  Edit edit_near_a_body();
  void bury_bodies();
  Polygon blast(Point64 centre, std::int64_t radius);
  int balls_and_boxes() const;

  PhysicsScenarioOptions options_;
  Random random_;
  GameDriver game_;
  PhysicsScene scene_;
  ScenarioStats stats_;
};

// The world of the scenario: rock (2) with hills over bedrock (1), dirt (3) on top, a few caves.
Landscape scene_world(std::int64_t size);

}  // namespace edgeland::box2d
