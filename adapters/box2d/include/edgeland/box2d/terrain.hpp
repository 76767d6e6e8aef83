#pragma once
// The game driver's updates (edgeland/game/game_driver.hpp) as Box2D 2.4 fixtures and bodies
// (adapters/box2d/README.md): the static terrain as bodies whose fixtures are the surface
// chains, replaced per update only where the chains changed; and debris as dynamic bodies of
// convex pieces. Everything geometric comes from the game layer; this adapter converts units.
//
//   GameDriver game(world, options);
//   box2d::Terrain terrain(b2world, game, {.units_per_metre = 32});
//   each frame:
//     const GameUpdate u = game.apply(edits);
//     terrain.apply(u);                                   // between two steps
//     for (const Debris& d : u.debris) make_debris_body(b2world, d, terrain.units());
//     b2world.Step(...);
//
// UNITS. One rule: engine = (landscape - origin) / units_per_metre, origin the world box's
// corner unless given. Box2D stores floats: a landscape point is exact in them only within 2^24
// units of the origin (at a power-of-two scale; a unit apart stays a unit apart), so a world
// whose box reaches farther is refused (OutOfEngineRange) rather than rounded in silence or left
// to trip Box2D's asserts.
#include <box2d/box2d.h>

#include <array>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "edgeland/engine/units.hpp"
#include "edgeland/game/game_driver.hpp"

namespace edgeland::box2d {

// How far from the origin (per axis, in landscape units) a point may lie for Box2D's floats.
inline constexpr std::int64_t kMaxEngineOffset = std::int64_t{1} << 24;

// A point the engine's floats cannot hold exactly: `point` lies more than kMaxEngineOffset
// units from the origin `origin` along an axis.
class EDGELAND_EXPORT OutOfEngineRange : public Error {
 public:
  OutOfEngineRange(Point64 point, Point64 origin);
  Point64 point, origin;
  std::int64_t limit = kMaxEngineOffset;
};

// Throws OutOfEngineRange unless p lies within kMaxEngineOffset of the origin on both axes.
void require_in_engine_range(Point64 p, Point64 origin);

b2Vec2 to_b2(const EngineUnits& units, Point64 p);

struct TerrainOptions {
  double units_per_metre = 1;  // landscape units in one Box2D metre (> 0)
  std::optional<Point64>
      origin;  // the landscape point at Box2D's (0, 0); default: the world's corner
  std::array<float, kMaterialCount> friction;  // by Material::value() (0: the wall); default 0.6
  // The world box cut into body_grid x body_grid regions, a static body per region with chains
  // (see Terrain). At least 1.
  std::int64_t body_grid = 16;
  // Broad-phase proxies reserved when the terrain is built (see Terrain, BROAD PHASE): unset,
  // twice the terrain's own and at least kDefaultReservedProxies; 0, none.
  std::optional<std::size_t> reserve_proxies;
  TerrainOptions() { friction.fill(0.6f); }
};

inline constexpr std::size_t kDefaultReservedProxies = std::size_t{1} << 14;

// The terrain: one b2ChainShape fixture per run of one material of a surface chain (the chain
// cut where its material changes, each run keeping the ghosts of its neighbours, so the joints
// stay smooth), on static bodies: the world box is cut into a grid of regions (16 x 16 by
// default) and a chain's fixtures go on the body of the region holding its cell's lower-left
// corner. Not one body for the world, because Box2D's DestroyFixture searches its body's whole
// fixture list (on one body, replacing a cell's chains cost 0.8 ms per explosion at 14,000
// fixtures, bench/README.md "Game layer"); not one per cell either, because every b2World::Step
// walks every body, static ones too (0.5-0.9 ms a frame at 16,000 bodies). Fixture user data
// holds the material.
//
// BROAD PHASE. Box2D 2.4 keeps every fixture's proxies in a dynamic tree whose node pool doubles
// when full (b2DynamicTree::AllocateNode: a new array, a copy, a new free list: O(capacity)), at
// about 8,192, 16,384, 32,768 ... proxies: a frame that passes such a count paid 0.7, 1.4,
// 2.4 ms more inside one CreateFixture (measured in thread CPU time; 5.5-9.5 ms in a loaded
// game, issue 35). The pool never shrinks, so the terrain reserves it once when built: a
// temporary chain far from the world with that many edges is made, forgotten by one step of
// zero length (b2World::Step(0, 0, 0): no body moves; Box2D's step also clears forces) and
// destroyed, its nodes left in the pool's free list. Then no fixture the updates create pays a
// doubling until the terrain outgrows the reserve.
class Terrain {
 public:
  // The fixtures of every chain the game has now. Throws OutOfEngineRange.
  Terrain(b2World& world, const GameDriver& game, const TerrainOptions& options = {});
  ~Terrain();
  Terrain(const Terrain&) = delete;
  Terrain& operator=(const Terrain&) = delete;

  // One update's chains (every update, in order): the fixtures of the removed chains destroyed,
  // of the added ones created. Call it between two b2World::Step calls.
  void apply(const GameUpdate& update);

  // The static bodies of the terrain, one per region with chains, in no particular order.
  std::vector<b2Body*> bodies() const;
  std::size_t fixture_count() const;
  const EngineUnits& units() const { return units_; }

 private:
  void reserve_proxies(std::size_t count);
  std::size_t region_of(const Box64& cell) const;
  b2Body* body_of(std::size_t region);
  void add(ChainId id, const SurfaceChain& chain);
  void remove(ChainId id, std::vector<std::size_t>& emptied);

  b2World& world_;
  EngineUnits units_;
  std::array<float, kMaterialCount> friction_;
  Box64 world_box_;
  std::int64_t grid_;
  std::vector<b2Body*> bodies_;  // per region, row by row; null where it has no chains
  struct ChainFixtures {
    std::size_t region = 0;
    std::vector<b2Fixture*> fixtures;
  };
  std::unordered_map<ChainId, ChainFixtures> fixtures_;
  std::vector<b2Vec2> vertices_;  // scratch
};

struct DebrisOptions {
  float density = 1.0f;
  float friction = 0.6f;
  float restitution = 0.1f;
};

// Debris as a dynamic body at its exact centroid: one b2PolygonShape fixture per convex piece
// (GameOptions::max_piece_vertices must be at most b2_maxPolygonVertices); fixture user data
// holds the material. The mass is computed once, after every fixture is made (Box2D recomputes
// it per fixture otherwise: quadratic in the pieces). Returns the body (the caller owns it
// through the world). Throws OutOfEngineRange.
b2Body* make_debris_body(b2World& world, const Debris& debris, const EngineUnits& units,
                         const DebrisOptions& options = {});

}  // namespace edgeland::box2d
