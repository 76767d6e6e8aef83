#pragma once
// A Box2D 2.4 world kept in step with a landscape (adapters/box2d/README.md): the static terrain
// as bodies whose fixtures are the landscape's surface chains, replaced per change set only
// where the chains changed; and detached debris islands as dynamic bodies of convex pieces.
// Everything geometric comes from the game layer (game/); this adapter only converts units.
#include <box2d/box2d.h>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "edgeland/engine/units.hpp"
#include "edgeland/game/islands.hpp"
#include "edgeland/game/surface_tracker.hpp"

namespace edgeland::box2d {

b2Vec2 to_b2(const EngineUnits& units, Point64 p);

struct TerrainOptions {
  SurfaceOptions surface;  // what is solid; the border as a wall or not
  EngineUnits units;       // the origin defaults to the world box's corner (see Terrain)
  std::array<float, kMaterialCount> friction;  // by Material::value() (0: the wall); default 0.6
  // The world box cut into body_grid x body_grid regions, a static body per region with chains
  // (see Terrain). At least 1.
  std::int64_t body_grid = 16;
  TerrainOptions() { friction.fill(0.6f); }
};

// The terrain: one b2ChainShape fixture per run of one material of a surface chain (the chain
// cut where its material changes, each run keeping the ghosts of its neighbours, so the joints
// stay smooth), on static bodies: the world box is cut into a grid of regions (16 x 16 by
// default) and a chain's fixtures go on the body of the region holding its cell's lower-left
// corner. Not one body for the world, because Box2D's DestroyFixture searches its body's whole
// fixture list (on one body, replacing a cell's chains cost 0.8 ms per explosion at 14,000
// fixtures, bench/README.md "Game layer"); not one per cell either, because every b2World::Step
// walks every body, static ones too (0.5-0.9 ms a frame at 16,000 bodies). Fixture user data
// holds the material.
class Terrain {
 public:
  // Builds the fixtures of every chain. With the default origin (0, 0) the world box's corner is
  // taken as the origin.
  Terrain(b2World& world, const Landscape& land, const TerrainOptions& options = {});
  ~Terrain();
  Terrain(const Terrain&) = delete;
  Terrain& operator=(const Terrain&) = delete;

  // The landscape after one edit (every edit, in order): the fixtures of the chains that changed
  // are destroyed and created. Call it between two b2World::Step calls: both happen here, so no
  // body ever sees a missing wall. Returns the chain update applied.
  ChainUpdate update(const Landscape& land, const ChangeSet& changes);
  // After any other change (a restored snapshot, a load).
  ChainUpdate resync(const Landscape& land);

  // The static bodies of the terrain, one per region with chains, in no particular order.
  std::vector<b2Body*> bodies() const;
  std::size_t fixture_count() const;
  const EngineUnits& units() const { return units_; }
  const SurfaceTracker& tracker() const { return tracker_; }

 private:
  std::size_t region_of(const Box64& cell) const;
  b2Body* body_of(std::size_t region);
  void add(ChainId id, const SurfaceChain& chain);
  void remove(ChainId id, std::vector<std::size_t>& emptied);
  void apply(const ChainUpdate& update);

  b2World& world_;
  EngineUnits units_;
  std::array<float, kMaterialCount> friction_;
  SurfaceTracker tracker_;
  Box64 world_box_;
  std::int64_t grid_;
  std::vector<b2Body*> bodies_;  // per region, row by row; null where it has no chains
  struct ChainFixtures {
    std::size_t region = 0;
    std::vector<b2Fixture*> fixtures;
  };
  std::unordered_map<ChainId, ChainFixtures> fixtures_;
};

struct DebrisOptions {
  float density = 1.0f;
  float friction = 0.6f;
  float restitution = 0.1f;
  std::size_t max_piece_vertices = b2_maxPolygonVertices;
};

// A detached island as a dynamic body at its exact centroid: one b2PolygonShape fixture per
// convex piece (kernel convex_pieces) of each of its polygons; fixture user data holds the
// material. Returns the body (the caller owns it through the world).
b2Body* make_debris_body(b2World& world, const DetachedIsland& island, const EngineUnits& units,
                         const DebrisOptions& options = {});

}  // namespace edgeland::box2d
