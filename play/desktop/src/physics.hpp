#pragma once
// The desktop demo's physics: a Box2D 2.4 world whose static terrain follows the landscape from
// its change sets, and the balls and boxes dropped on it. Engine units are metres,
// `units_per_metre` world units each, taken relative to the world box's corner (a world near
// the int32 bound would otherwise lose its vertices to float rounding).
//
// The terrain today: one static body per solid polygon, a chain loop around it, rebuilt for the
// polygons a change set names. This is the part the game layer's Box2D adapter (edgeland::box2d:
// per-cell surface chains with ghost vertices, no seams) replaces.
#include <box2d/box2d.h>

#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

#include "edgeland/spatial/landscape.hpp"

namespace edgeland::play {

enum class BodyKind : std::uint8_t { kBall, kBox };

struct DynamicBody {
  b2Body* body = nullptr;
  BodyKind kind = BodyKind::kBall;
  double size = 0;  // world units: radius or half side
};

class Physics {
 public:
  Physics(const Box64& world, double units_per_metre, std::function<bool(Material)> solid);

  // The terrain colliders of the polygons a change set removed and added.
  void apply(const ChangeSet& changes);
  // All terrain colliders again (after undo, redo or a load).
  void reset(const Landscape& landscape);

  void drop_ball(Point64 at, double radius);
  void drop_box(Point64 at, double half);
  // One fixed step; bodies that fell below the world are removed.
  void step(double seconds);
  // Removes the bodies whose centre `covered` says is now inside solid material (a fill
  // buried them); returns how many.
  std::size_t remove_buried(const std::function<bool(Point64)>& covered);

  // A body's centre and angle in world units / radians.
  Point64 centre(const DynamicBody& body) const;
  double world_x(float metres_x) const;
  double world_y(float metres_y) const;
  const std::vector<DynamicBody>& bodies() const noexcept { return bodies_; }
  std::size_t terrain_bodies() const noexcept { return terrain_.size(); }

 private:
  b2Vec2 metres(Point64 p) const;
  void add_terrain(PolygonId id, Material material, const Polygon& polygon);
  void remove_terrain(PolygonId id);

  Box64 box_;
  double k_;
  std::function<bool(Material)> solid_;
  std::unique_ptr<b2World> world_;
  std::unordered_map<PolygonId, b2Body*> terrain_;
  std::vector<DynamicBody> bodies_;
};

}  // namespace edgeland::play
