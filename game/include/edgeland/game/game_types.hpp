#pragma once
// The game layer's vocabulary (game/README.md): what a game receives from the landscape and
// what it configures, apart from the driver that produces it (game_driver.hpp). Plain data:
// integer points, ids, materials. An engine's adapter (adapters/box2d) or a front end only
// translates these.
//
//   SurfaceChain   a run of the collision surface inside one cell, solid on its LEFT, with the
//                  ghost vertices before and after it (surface_chains.hpp says what the surface
//                  is and why chains are cut at cell lines).
//   ChainUpdate    which chains to remove and to add after a change, by id.
//   PolygonMesh    one landscape polygon as triangles over its own vertices.
//   MeshUpdate     which meshes to drop and to build, by polygon id.
//   Debris         an island taken out of the landscape, as the shapes of a dynamic body.
//   GameOptions    what is solid, what never falls, what the driver keeps and how much debris
//                  work one update may do.
//   GameUpdate     everything one update changed, for a game to apply between two steps.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "edgeland/game/physics_materials.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/triangulate.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland {

// What the collision surface is made of (surface_chains.hpp).
struct SurfaceOptions {
  PhysicsMaterials materials;
  // The world border as a wall around the non-solid parts of the world (chains along the border,
  // material 0), so no body leaves the world. Default: the border is not exported.
  bool border_wall = false;
  friend bool operator==(const SurfaceOptions&, const SurfaceOptions&) = default;
};

// A chain of the surface: solid on its left, at least 2 points (closed: 3, the first not
// repeated), no two consecutive points equal, no three consecutive on a line unless the material
// changes at the middle one.
struct SurfaceChain {
  std::vector<Point64> points;
  // materials[i]: the solid material left of the segment points[i] -> points[i + 1] (for a
  // closed chain the last segment runs back to points[0]); 0 along a border wall.
  std::vector<Material> materials;
  bool closed = false;
  Point64 ghost_prev;  // the surface point before points.front()
  Point64 ghost_next;  // the surface point after points.back()
  Box64 cell;          // the cell the chain lies in (the world box for whole loops)
  friend bool operator==(const SurfaceChain&, const SurfaceChain&) = default;
};

// Ids are never reused: a chain that changes in any way (a point, a material, a ghost) is a new
// chain with a new id.
using ChainId = std::uint64_t;

struct ChainUpdate {
  std::vector<ChainId> removed;                         // ascending
  std::vector<std::pair<ChainId, SurfaceChain>> added;  // by ascending id
  bool empty() const noexcept { return removed.empty() && added.empty(); }
};

// One polygon's mesh: its own vertices and counter-clockwise index triples (kernel
// triangulate(): exact, n - 2 triangles, none degenerate, areas summing to the polygon's).
struct PolygonMesh {
  PolygonId id = 0;
  Material material = kEmpty;
  std::vector<Point64> vertices;    // the polygon's own vertices (a vertex buffer)
  std::vector<Triangle> triangles;  // counter-clockwise index triples into `vertices`
  friend bool operator==(const PolygonMesh&, const PolygonMesh&) = default;
};

struct MeshUpdate {
  std::vector<PolygonId> dropped;  // ascending: the meshes to delete
  std::vector<PolygonMesh> built;  // by ascending id: the meshes to add
};

// A convex piece of a debris body: one fixture (at most GameOptions::max_piece_vertices
// vertices, counter-clockwise, exact).
struct DebrisPiece {
  Material material = kEmpty;
  Polygon polygon;
};

// An island taken out of the landscape (islands.hpp says what an island is), ready to become a
// dynamic body: its region per material as maximal polygons (merged across cell lines: the
// body's outline, not the cells it was cut from), those polygons' convex pieces, and its exact
// area and centroid (the body's origin).
// One material's part of an island as maximal polygons: its polygons merged across the cell
// lines they were cut at (clip's merge_tiles), holes split as the clipper splits them.
struct IslandRegion {
  Material material = kEmpty;
  PolygonSet polygons;
};

struct Debris {
  using Region = IslandRegion;
  std::vector<Region> regions;      // ascending material
  std::vector<DebrisPiece> pieces;  // the convex pieces of every region polygon, in order
  std::vector<PolygonMesh> meshes;  // each region polygon's mesh, in order (GameOptions::meshes;
                                    // ids 0: these polygons are not the landscape's)
  Int128 twice_area = 0;
  RationalPoint centroid;
  Box64 bounds;
};

struct GameOptions {
  SurfaceOptions surface;
  bool meshes = true;  // GameUpdate::meshes is filled
  // Islands are found and detached as debris (on by default). Off: no island work at all.
  bool debris = true;
  // Debris bodies' convex pieces have at most this many vertices (3 or more, else the driver
  // refuses the options with InvalidArgument; Box2D 2.4's b2_maxPolygonVertices is 8).
  std::size_t max_piece_vertices = 8;
  // The island work one update may do, in island vertices (a step costs the vertices it reads;
  // about 0.3-0.4 us each on the bench machine): islands found wait in a queue and are detached
  // oldest first while the budget lasts (the first one gets a step whatever it costs, unless it
  // was found in this update). No island waits more than `max_debris_wait` updates: one that
  // old is detached whatever the budget.
  std::size_t debris_budget = 8192;
  std::size_t max_debris_wait = 3;
};

// What one update did (for profiling, and for the tests that check its bounds).
struct GameWork {
  std::size_t cells_scanned = 0;    // cells read and cut into boundary pieces (stage 1)
  std::size_t boundary_passes = 0;  // stage-1 passes run (one per cell scanned)
  std::size_t cells_traced = 0;     // cells whose chains were traced (scanned or re-covered)
  std::size_t islands_found = 0;    // new islands (joining the debris queue)
  std::size_t islands_detached = 0;
};

// What one GameDriver call changed. Apply it between two physics steps: remove the chains and
// meshes named, add the new ones, make a body of every debris. Ids in `removed` never come back.
struct GameUpdate {
  // Every polygon the update removed and added (the edits' and the detaches' together; a
  // polygon both added and removed within the update appears in neither), the cells it
  // replaced, the change of area per material.
  ChangeSet changes;
  ChainUpdate chains;
  MeshUpdate meshes;  // empty unless GameOptions::meshes
  std::vector<Debris> debris;
  std::size_t debris_waiting = 0;  // islands found and not yet detached (see debris_budget)
  GameWork work;
};

}  // namespace edgeland
