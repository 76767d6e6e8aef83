#pragma once
// The desktop demo's physics: a Box2D 2.4 world whose static terrain follows the game driver's
// updates (the Box2D adapter, edgeland::box2d::Terrain: per-cell surface chains with ghost
// vertices, no seams), the balls and boxes dropped on it, and the debris the updates hand out
// (edgeland::box2d::make_debris_body). Engine units are metres, `units_per_metre` world units
// each, relative to the world box's corner.
#include <box2d/box2d.h>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "edgeland/box2d/terrain.hpp"
#include "edgeland/game/game_driver.hpp"

namespace edgeland::play {

enum class BodyKind : std::uint8_t { kBall, kBox, kDebris };

struct DynamicBody {
  b2Body* body = nullptr;
  BodyKind kind = BodyKind::kBall;
  double size = 0;  // world units: radius or half side
  // Debris, for drawing: its polygons' vertices in world units around the body's origin (the
  // island's centroid), their colours' materials, and the triangles over them (render meshes).
  struct Piece {
    Material material = kEmpty;
    std::vector<std::pair<double, double>> vertices;
    std::vector<int> triangles;  // three indices each
  };
  std::vector<Piece> shape{};
};

class Physics {
 public:
  Physics(const GameDriver& game, double units_per_metre);

  // One update of the game: the terrain's chains, and a body per debris.
  void apply(const GameUpdate& update);

  void drop_ball(Point64 at, double radius);
  void drop_box(Point64 at, double half);
  // One fixed step; bodies that fell below the world are removed.
  void step(double seconds);
  // Removes the balls and boxes whose centre `covered` says is now inside solid material (a fill
  // buried them); returns how many.
  std::size_t remove_buried(const std::function<bool(Point64)>& covered);
  // Removes the debris (after undo, redo or a load the islands are back in the landscape).
  void remove_debris();

  Point64 centre(const DynamicBody& body) const;
  double world_x(float metres_x) const;
  double world_y(float metres_y) const;
  const std::vector<DynamicBody>& bodies() const noexcept { return bodies_; }
  std::size_t terrain_fixtures() const { return terrain_->fixture_count(); }

 private:
  b2Vec2 metres(Point64 p) const;
  void add_debris(const Debris& debris);

  Box64 box_;
  EngineUnits units_;
  std::unique_ptr<b2World> world_;
  std::optional<box2d::Terrain> terrain_;
  std::vector<DynamicBody> bodies_;
};

}  // namespace edgeland::play
