#pragma once
// The demos' one Box2D scene (issue 38): a Box2D 2.4 world whose static terrain follows a game
// driver's updates (the Box2D adapter's Terrain: per-cell surface chains with ghost vertices, no
// seams), the balls and boxes dropped on it, and a dynamic body for each debris island the
// updates hand out (make_debris_body). PhysicsScene follows a driver that its owner keeps and
// edits: the desktop demo's session (play/desktop), or the seeded scenario of tests/box2d and
// `edgeland demo --physics` (physics_scenario.hpp).
#include <box2d/box2d.h>

#include <cstdint>
#include <functional>
#include <vector>

#include "edgeland/box2d/terrain.hpp"

namespace edgeland::box2d {

enum class BodyKind : std::uint8_t { kBall, kBox, kDebris };

// How a ball or a box meets the terrain and the other bodies (density 1).
struct BodySurface {
  float friction = 0.5f;
  float restitution = 0;
};

struct SceneBody {
  b2Body* body = nullptr;
  BodyKind kind = BodyKind::kBall;
  double size = 0;    // landscape units: a ball's radius, a box's half side (0 for debris)
  float start_y = 0;  // engine units: where a debris body was made
  // Debris, for drawing: the island's meshes (the driver's, in landscape coordinates) and its
  // centroid, which is the body's origin.
  std::vector<PolygonMesh> meshes{};
  EngineVec centroid{};
};

// What the scene has done, and where its time went (wall clock; reporting only).
struct SceneStats {
  int steps = 0, detached = 0;
  std::size_t chains_removed = 0, chains_added = 0;
  double collider_seconds = 0, debris_seconds = 0, step_seconds = 0;
};

class PhysicsScene {
 public:
  // The terrain of `game`'s landscape; `game` must outlive the scene. Its owner makes the edits
  // and hands each update to apply().
  PhysicsScene(const GameDriver& game, const TerrainOptions& options);
  PhysicsScene(const PhysicsScene&) = delete;
  PhysicsScene& operator=(const PhysicsScene&) = delete;

  // One update of the driver, between two steps (no body ever sees a missing wall): the
  // terrain's chains, and a body for each debris.
  void apply(const GameUpdate& update);
  // A ball of `radius`, or a box of half side `half` turned by `angle` radians (landscape units),
  // centred at `at`.
  void drop_ball(Point64 at, double radius, const BodySurface& surface = {});
  void drop_box(Point64 at, double half, float angle = 0, const BodySurface& surface = {});
  // One step of `seconds` (8 velocity and 3 position iterations).
  void step(float seconds = 1.0f / 60.0f);
  // Takes the bodies `which` picks out of the world, in order; returns how many.
  std::size_t remove_bodies(const std::function<bool(const SceneBody&)>& which);

  // The balls and boxes (not debris: a centroid may lie outside its own shape) whose centre lies
  // in material the driver takes as solid.
  std::vector<Point64> centres_in_solid() const;
  // Any body whose centre left the world's box.
  std::vector<Point64> centres_outside_world() const;
  // A body's position as the nearest landscape point, and unrounded (for drawing).
  Point64 centre(const b2Body* body) const;
  EngineVec position(const b2Body* body) const;
  // The landscape box around a body's fixtures, one unit wider on every side.
  Box64 box_of(const b2Body* body) const;

  const GameDriver& game() const { return game_; }
  const Landscape& land() const { return game_.landscape(); }
  b2World& world() { return world_; }
  const Terrain& terrain() const { return terrain_; }
  const std::vector<SceneBody>& bodies() const { return bodies_; }
  const SceneStats& stats() const { return stats_; }

 private:
  void add_body(const b2BodyDef& def, const b2Shape& shape, BodyKind kind, double size,
                const BodySurface& surface);

  const GameDriver& game_;
  b2World world_;
  Terrain terrain_;
  std::vector<SceneBody> bodies_;
  SceneStats stats_;
};

}  // namespace edgeland::box2d
