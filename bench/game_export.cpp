// The whole world at once (issue 26, "Speed"; bench/README.md, "Game layer"): the 8192 x 8192
// world of `edgeland demo` (demo/: edgeland/demo/landscape.hpp) after
// EDGELAND_GAME_DEMO_EDITS of its players' actions (default 6000, the demo's own default),
// exported as a game loading it would: surface_chains, surface_loops, all_meshes, find_islands,
// and a box2d::Terrain built from scratch; beside it, the same world rasterised into a bitmap
// and a PixelTerrain built from scratch (every 64 x 64 chunk traced and its loops created).
// Water is not solid and bedrock is anchored. Each time is the fastest of EDGELAND_GAME_REPEATS.
// Name game_export/demo/EDITS.
#include <functional>
#include <memory>
#include <string>

#include "edgeland/box2d/terrain.hpp"
#include "edgeland/demo/landscape.hpp"
#include "edgeland/game/islands.hpp"
#include "edgeland/game/render_meshes.hpp"
#include "edgeland/game/surface_chains.hpp"
#include "game_common.hpp"
#include "pixel_terrain.hpp"

namespace edgeland::bench {
namespace {

std::size_t demo_edits() { return env_count("EDGELAND_GAME_DEMO_EDITS", 6000); }

SurfaceOptions demo_surface() {
  SurfaceOptions o;
  o.materials.set_solid(demo::kWater, false).set_anchored(demo::kBedrock);
  return o;
}

// The landscape's polygons painted into a bitmap of the same box (every square takes the
// material of the polygon holding its centre).
BitmapWorld rasterise(const Landscape& world) {
  BitmapWorld bitmap(world.world(), kEmpty);
  world.polygons_in(world.world(), [&](const PolygonView& v) {
    bitmap.paint(PolygonSet{*v.polygon}, v.material);
    return true;
  });
  return bitmap;
}

// The fastest of the repeats of f(), in seconds.
double fastest(const std::function<void()>& f) {
  double best = 1e300;
  for (std::size_t r = 0; r < game_repeats(); ++r) best = std::min(best, seconds_of(f));
  return best;
}

// The fastest of the repeats of building a terrain (make(world) returns it) in a new b2World.
// The world then takes one Step and is torn down, untimed: before a step every DestroyProxy
// searches all new proxies (b2BroadPhase's move buffer), which is no part of loading a world.
template <class Make>
double fastest_build(Make&& make) {
  double best = 1e300;
  for (std::size_t r = 0; r < game_repeats(); ++r) {
    b2World world(b2Vec2(0, -10));
    decltype(make(world)) terrain;
    best = std::min(best, seconds_of([&] { terrain = make(world); }));
    world.Step(1.0f / 60.0f, 8, 3);
  }
  return best;
}

void run_game_export(benchmark::State& state) {
  const Landscape world = demo::demo_landscape(demo::kDemoWorld, 1, demo_edits());
  const SurfaceOptions surface = demo_surface();
  const BitmapWorld bitmap = rasterise(world);
  box2d::TerrainOptions terrain_options;
  terrain_options.units_per_metre = kUnitsPerMetre;
  GameOptions game_options;
  game_options.surface = surface;
  game_options.debris = false;  // the terrain of the world as it is
  PixelTerrain::Options pixel_options;
  for (std::size_t m = 1; m < kMaterialCount; ++m)
    pixel_options.solid[m] = surface.materials.is_solid(static_cast<Material>(m));
  pixel_options.units_per_metre = kUnitsPerMetre;
  std::size_t chains = 0, chain_vertices = 0, loops = 0, triangles = 0, islands = 0;
  std::size_t terrain_fixtures = 0, pixel_fixtures = 0, pixel_vertices = 0;
  for (auto _ : state) {
    state.counters["surface_chains_ms"] = 1e3 * fastest([&] {
                                            const std::vector<SurfaceChain> c =
                                                surface_chains(world, surface);
                                            chains = c.size();
                                            chain_vertices = 0;
                                            for (const SurfaceChain& chain : c)
                                              chain_vertices += chain.points.size();
                                          });
    state.counters["surface_loops_ms"] =
        1e3 * fastest([&] { loops = surface_loops(world, surface).size(); });
    state.counters["all_meshes_ms"] = 1e3 * fastest([&] {
                                        triangles = 0;
                                        for (const PolygonMesh& m : all_meshes(world))
                                          triangles += m.triangles.size();
                                      });
    state.counters["find_islands_ms"] =
        1e3 * fastest([&] { islands = find_islands(world, surface.materials).size(); });
    // The terrain from a game driver made at once: its chains, then Box2D's fixtures.
    state.counters["terrain_build_ms"] =
        1e3 * fastest_build([&](b2World& b2) {
          const GameDriver game(world, game_options);
          auto terrain = std::make_unique<box2d::Terrain>(b2, game, terrain_options);
          terrain_fixtures = terrain->fixture_count();
          return terrain;
        });
    state.counters["pixel_build_ms"] =
        1e3 * fastest_build([&](b2World& b2) {
          auto terrain = std::make_unique<PixelTerrain>(b2, bitmap, pixel_options);
          pixel_fixtures = terrain->fixture_count();
          pixel_vertices = terrain->vertex_count();
          return terrain;
        });
  }
  const LandscapeStats s = world.stats();
  state.counters["polygons"] = static_cast<double>(s.polygons);
  state.counters["vertices"] = static_cast<double>(s.vertices);
  state.counters["cells"] = static_cast<double>(s.cells);
  state.counters["chains"] = static_cast<double>(chains);
  state.counters["chain_vertices"] = static_cast<double>(chain_vertices);
  state.counters["loops"] = static_cast<double>(loops);
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["islands"] = static_cast<double>(islands);
  state.counters["terrain_fixtures"] = static_cast<double>(terrain_fixtures);
  state.counters["pixel_fixtures"] = static_cast<double>(pixel_fixtures);
  state.counters["pixel_vertices"] = static_cast<double>(pixel_vertices);
}

}  // namespace

void register_game_export_benchmarks() {
  const std::string name = "game_export/demo/" + std::to_string(demo_edits());
  benchmark::RegisterBenchmark(name.c_str(),
                               [](benchmark::State& state) {
                                 if (!guarded(state, [&] { run_game_export(state); })) return;
                               })
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
}

}  // namespace edgeland::bench
