#pragma once
// The physics scene of the Box2D adapter's test and of `edgeland demo --physics` (one scene,
// so the demo shows what the test checks): a layered world with hills (bedrock, rock, dirt), 200
// balls and boxes resting and rolling on it, and a stream of blasts and fills near them. Each
// frame's edits go to the game driver as one batch; its update goes to the terrain's fixtures,
// its debris become bodies, and the bodies its fills buried leave the play. Deterministic: a
// seeded generator, a fixed step.
#include <box2d/box2d.h>

#include <cstdint>
#include <vector>

#include "edgeland/box2d/terrain.hpp"
#include "edgeland/kernel/splitmix64.hpp"

namespace edgeland::box2d {

struct PhysicsSceneOptions {
  std::uint64_t seed = 2026;
  std::int64_t size = 4096;     // the world is size x size units
  double units_per_metre = 32;  // 4096 units = 128 m
  int bodies = 200;             // balls and boxes in play (buried ones are replaced)
  int edits_per_frame = 3;
};

struct SceneBody {
  b2Body* body = nullptr;
  bool debris = false;
  float start_y = 0;  // where a debris body was made (engine units)
};

// What the scene has done, and where its time went (wall clock; reporting only).
struct SceneStats {
  int frames = 0, settled = 0, edits = 0, detached = 0,
      buried = 0;  // settled: frames without edits
  std::size_t chains_removed = 0, chains_added = 0;
  double game_seconds = 0, collider_seconds = 0, debris_seconds = 0, step_seconds = 0;
};

class PhysicsScene {
 public:
  explicit PhysicsScene(const PhysicsSceneOptions& options = {});
  PhysicsScene(const PhysicsScene&) = delete;
  PhysicsScene& operator=(const PhysicsScene&) = delete;

  // Steps without edits (the bodies land).
  void settle(int frames);
  // `edits_per_frame` edits near random bodies, then one step of 1/60 s.
  void frame();

  // The balls and boxes (not debris) whose centre lies in solid material.
  std::vector<Point64> centres_in_solid() const;
  // Any body whose centre left the world's box.
  std::vector<Point64> centres_outside_world() const;
  Point64 centre(const b2Body* body) const;

  static PhysicsMaterials materials();  // bedrock (1) anchored
  static GameOptions game_options();
  static TerrainOptions terrain_options(const PhysicsSceneOptions& options);

  const Landscape& land() const { return game_.landscape(); }
  const GameDriver& game() const { return game_; }
  b2World& world() { return world_; }
  const Terrain& terrain() const { return terrain_; }
  const std::vector<SceneBody>& bodies() const { return bodies_; }
  const SceneStats& stats() const { return stats_; }

 private:
  class Random {
   public:
    explicit Random(std::uint64_t seed) : source_(seed) {}
    std::int64_t in(std::int64_t lo, std::int64_t hi);  // [lo, hi]

   private:
    edgeland::SplitMix64 source_;
  };

  void drop_bodies(int count);
  Edit edit_near_a_body();
  void apply(const GameUpdate& update);
  void bury_bodies();
  Box64 box_of(b2Body* body) const;
  Polygon blast(Point64 centre, std::int64_t radius);
  int balls_and_boxes() const;

  PhysicsSceneOptions options_;
  Random random_;
  GameDriver game_;
  b2World world_;
  Terrain terrain_;
  std::vector<SceneBody> bodies_;
  SceneStats stats_;
};

// The world of the scene: rock (2) with hills over bedrock (1), dirt (3) on top, a few caves.
Landscape scene_world(std::int64_t size);

}  // namespace edgeland::box2d
