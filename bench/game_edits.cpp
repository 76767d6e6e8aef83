// Per edit, edgeland's game layer against the pixel pipeline a game would otherwise run
// (issue 26, "Speed"; bench/README.md, "Game layer"), on the landscape benchmark's edits of an
// 8192 x 8192 world (landscape_shapes.hpp):
//   explosion: EDITS 32-gons of radius 40 carved into solid rock (material 1);
//   tunnel:    EDITS digger strokes (capsules of radius 20) carved into solid rock;
//   fill:      EDITS 32-gons of radius 40 of material 2 filled into the world the explosions
//              left (about half of it carved).
// Every edit, in one process, both sides one after the other (which one first alternates
// between repeats), so both see the same machine; times are this thread's CPU time
// (game_common.hpp, ThreadClock: the machine is shared, and a preempted edit would otherwise count
// the wait):
//   edgeland: GameDriver::apply (the landscape edit, the chains, islands, debris and meshes that
//             follow from it), then box2d::Terrain::apply (the changed chains' fixtures
//             destroyed and created) and a debris body per island: the end-to-end time; and, as
//             a row of its own, the same edit on a plain landscape (the edit's share);
//   pixel:    BitmapWorld::paint, the 64 x 64 chunks the shape's box meets traced again
//             (PixelTerrain::trace) and their fixtures rebuilt (PixelTerrain::rebuild): the
//             end-to-end time.
// Each side has its own b2World (gravity, no other bodies) and its terrain on static bodies, one
// per region of the same 16 x 16 grid (box2d::Terrain, pixel_terrain.hpp). After
// every edit each world takes one Step (1/60 s), as a game's next frame would, timed as a row of
// its own and not part of the end-to-end time: Box2D only forgets its new proxies in a step
// (b2BroadPhase's move buffer, searched linearly by every DestroyProxy), so without steps the
// fixture rebuilds of either side would grow quadratic.
// Names game_edit/WORKLOAD/EDITS; EDITS from EDGELAND_GAME_EDITS (default 10000), repeats from
// EDGELAND_GAME_REPEATS (default 5, each edit's fastest time per stage is kept).
#include <array>
#include <map>
#include <optional>
#include <string>

#include "edgeland/box2d/terrain.hpp"
#include "edgeland/game/render_meshes.hpp"
#include "game_common.hpp"
#include "landscape_shapes.hpp"
#include "pixel_terrain.hpp"

namespace edgeland::bench {
namespace {

constexpr Box64 kWorld{{0, 0}, {8192, 8192}};
constexpr Material kRock = 1, kFillMaterial = 2;

enum class Workload : std::uint8_t { kExplosion, kTunnel, kFill };
const char* workload_name(Workload w) {
  return w == Workload::kExplosion ? "explosion" : w == Workload::kTunnel ? "tunnel" : "fill";
}

std::size_t edit_count() { return env_count("EDGELAND_GAME_EDITS", 10000); }

const std::vector<ValidSet>& shapes(Workload w) {
  static std::map<Workload, std::vector<ValidSet>> cache;
  auto it = cache.find(w);
  if (it == cache.end()) {
    const std::size_t n = edit_count();
    it = cache
             .emplace(w, w == Workload::kExplosion ? explosions(kCarveSeed, n, kWorld)
                         : w == Workload::kTunnel  ? digger_strokes(kDigSeed, n, kWorld)
                                                   : explosions(kFillSeed, n, kWorld))
             .first;
  }
  return it->second;
}

// The stages timed per edit; kEdgeland and kPixel are the end-to-end sums.
enum Stage : std::size_t {
  kEdit,
  kGame,
  kTerrain,
  kDebris,
  kPaint,
  kTrace,
  kRebuild,
  kEdgeland,
  kPixel,
  kEdgelandStep,
  kPixelStep,
  kStageCount
};
constexpr std::array<const char*, kStageCount> kStageNames{
    "landscape_edit", "game_update",   "terrain_update", "debris_bodies",
    "bitmap_edit",    "chunk_trace",   "chunk_rebuild",  "edgeland",
    "pixel",          "edgeland_step", "pixel_step"};

// One frame of a b2World, as a game steps it between edits.
void step(b2World& world) { world.Step(1.0f / 60.0f, 8, 3); }

// What each edit did (the same in every repeat: the edits are deterministic).
struct Counts {
  double cells = 0, chains_removed = 0, chains_added = 0, triangles = 0;  // sums
  double chunks = 0, loops = 0;                                           // sums
  double islands = 0;                                                     // islands detached
  std::size_t max_traced = 0;  // GameUpdate::work.cells_traced, worst edit
  std::size_t terrain_fixtures = 0, pixel_fixtures = 0, pixel_vertices = 0;  // at the end
};

struct World2 {
  Landscape land;
  BitmapWorld bitmap;
};

struct Pass {
  std::array<std::vector<double>, kStageCount> seconds;
  Counts counts;
  std::optional<World2> end;
};

// One side's state during a pass.
struct EdgelandSide {
  b2World world{b2Vec2(0, -10)};
  Landscape plain;  // the same edits on a landscape alone: the edit's share
  GameDriver game;
  box2d::Terrain terrain;

  static box2d::TerrainOptions options() {
    box2d::TerrainOptions o;
    o.units_per_metre = kUnitsPerMetre;
    return o;
  }
  explicit EdgelandSide(const Landscape& start)
      : plain(start), game(start), terrain(world, game, options()) {
    step(world);
  }
};

struct PixelSide {
  b2World world{b2Vec2(0, -10)};
  BitmapWorld bitmap;
  PixelTerrain terrain;

  static PixelTerrain::Options options() {
    PixelTerrain::Options o;
    o.solid.fill(true);
    o.solid[kEmpty.value()] = false;
    o.units_per_metre = kUnitsPerMetre;
    return o;
  }
  explicit PixelSide(const BitmapWorld& start) : bitmap(start), terrain(world, bitmap, options()) {
    step(world);
  }
};

void edgeland_edit(EdgelandSide& e, Workload w, const ValidSet& shape, std::size_t i, Pass& p) {
  ThreadClock laps;
  benchmark::DoNotOptimize(w == Workload::kFill ? e.plain.fill(shape, kFillMaterial)
                                                : e.plain.carve(shape));
  p.seconds[kEdit][i] = laps.lap();
  const GameUpdate u =
      e.game.apply(w == Workload::kFill ? edgeland::Edit::fill(shape, kFillMaterial)
                                        : edgeland::Edit::carve(shape));
  p.seconds[kGame][i] = laps.lap();
  e.terrain.apply(u);
  p.seconds[kTerrain][i] = laps.lap();
  for (const Debris& d : u.debris) box2d::make_debris_body(e.world, d, e.terrain.units());
  p.seconds[kDebris][i] = laps.lap();
  step(e.world);
  p.seconds[kEdgelandStep][i] = laps.lap();
  p.seconds[kEdgeland][i] = p.seconds[kGame][i] + p.seconds[kTerrain][i] + p.seconds[kDebris][i];
  Counts& c = p.counts;
  c.cells += static_cast<double>(u.changes.cells.size());
  c.chains_removed += static_cast<double>(u.chains.removed.size());
  c.chains_added += static_cast<double>(u.chains.added.size());
  for (const PolygonMesh& m : u.meshes.built)
    c.triangles += static_cast<double>(m.triangles.size());
  c.islands += static_cast<double>(u.debris.size());
  c.max_traced = std::max(c.max_traced, u.work.cells_traced);
}

void pixel_edit(PixelSide& s, Workload w, const ValidSet& shape, std::size_t i, Pass& p) {
  ThreadClock laps;
  s.bitmap.paint(shape.polygons(), w == Workload::kFill ? kFillMaterial : kEmpty);
  p.seconds[kPaint][i] = laps.lap();
  const auto& traced = s.terrain.trace(s.bitmap, *bounding_box(shape.polygons()));
  p.seconds[kTrace][i] = laps.lap();
  s.terrain.rebuild(traced);
  p.seconds[kRebuild][i] = laps.lap();
  step(s.world);
  p.seconds[kPixelStep][i] = laps.lap();
  p.seconds[kPixel][i] = p.seconds[kPaint][i] + p.seconds[kTrace][i] + p.seconds[kRebuild][i];
  p.counts.chunks += static_cast<double>(traced.size());
  for (const auto& chunk : traced) p.counts.loops += static_cast<double>(chunk.loops.size());
}

Pass run_pass(const World2& start, Workload w, std::size_t repeat, bool keep_end) {
  const std::vector<ValidSet>& edits = shapes(w);
  Pass p;
  for (auto& s : p.seconds) s.assign(edits.size(), 0.0);
  EdgelandSide e(start.land);
  PixelSide s(start.bitmap);
  for (std::size_t i = 0; i < edits.size(); ++i) {
    if (repeat % 2 == 0) {
      edgeland_edit(e, w, edits[i], i, p);
      pixel_edit(s, w, edits[i], i, p);
    } else {
      pixel_edit(s, w, edits[i], i, p);
      edgeland_edit(e, w, edits[i], i, p);
    }
  }
  p.counts.terrain_fixtures = e.terrain.fixture_count();
  p.counts.pixel_fixtures = s.terrain.fixture_count();
  p.counts.pixel_vertices = s.terrain.vertex_count();
  if (keep_end) p.end.emplace(World2{e.game.landscape(), s.bitmap});
  return p;
}

// The explosions' end: the fill workload's start. Kept from the explosion benchmark, made
// here (untimed) when that was filtered out.
std::optional<World2>& explosion_end() {
  static std::optional<World2> end;
  return end;
}

World2 start_of(Workload w) {
  if (w != Workload::kFill) return {Landscape(kWorld, kRock), BitmapWorld(kWorld, kRock)};
  if (!explosion_end()) {
    World2 world{Landscape(kWorld, kRock), BitmapWorld(kWorld, kRock)};
    for (const ValidSet& shape : shapes(Workload::kExplosion)) {
      world.land.carve(shape);
      world.bitmap.carve(shape.polygons());
    }
    explosion_end().emplace(std::move(world));
  }
  return *explosion_end();
}

void report(benchmark::State& state, const std::array<Series, kStageCount>& series, const Counts& c,
            std::size_t edits) {
  for (std::size_t k = 0; k < kStageCount; ++k) report_series(state, kStageNames[k], series[k]);
  const auto at = [&](Stage s, double q) { return quantile(series[s].fastest, q); };
  state.counters["median_ratio"] = at(kEdgeland, 0.5) / at(kPixel, 0.5);
  state.counters["p99_ratio"] = at(kEdgeland, 0.99) / at(kPixel, 0.99);
  // The spread of the ratio of medians over the repeats: how much the machine moved.
  double lo = 1e300, hi = 0;
  for (std::size_t r = 0; r < series[kEdgeland].repeat_median.size(); ++r) {
    const double ratio = series[kEdgeland].repeat_median[r] / series[kPixel].repeat_median[r];
    lo = std::min(lo, ratio);
    hi = std::max(hi, ratio);
  }
  state.counters["repeat_median_ratio_min"] = lo;
  state.counters["repeat_median_ratio_max"] = hi;
  const double n = static_cast<double>(edits);
  state.counters["cells_per_edit"] = c.cells / n;
  state.counters["chains_removed_per_edit"] = c.chains_removed / n;
  state.counters["chains_added_per_edit"] = c.chains_added / n;
  state.counters["triangles_per_edit"] = c.triangles / n;
  state.counters["chunks_per_edit"] = c.chunks / n;
  state.counters["pixel_loops_per_edit"] = c.loops / n;
  state.counters["islands_detached"] = c.islands;
  state.counters["cells_traced_max"] = static_cast<double>(c.max_traced);
  state.counters["terrain_fixtures"] = static_cast<double>(c.terrain_fixtures);
  state.counters["pixel_fixtures"] = static_cast<double>(c.pixel_fixtures);
  state.counters["pixel_vertices"] = static_cast<double>(c.pixel_vertices);
}

void run_game_edit(benchmark::State& state, Workload w) {
  std::array<Series, kStageCount> series;
  Counts counts;
  std::optional<World2> end;
  for (auto _ : state) {
    const bool ok = guarded(state, [&] {
      const World2 start = start_of(w);
      for (std::size_t r = 0; r < game_repeats(); ++r) {
        Pass p = run_pass(start, w, r, r == 0);
        for (std::size_t k = 0; k < kStageCount; ++k) series[k].add_repeat(p.seconds[k]);
        if (r == 0) {
          counts = p.counts;
          end = std::move(p.end);
        }
      }
    });
    if (!ok) return;
    double total = 0;
    for (double s : series[kEdgeland].fastest) total += s;
    state.SetIterationTime(total);
  }
  if (!verify(state, World(end->land))) return;
  if (w == Workload::kExplosion) explosion_end() = std::move(end);
  report(state, series, counts, shapes(w).size());
}

}  // namespace

void register_game_edit_benchmarks() {
  const std::string edits = std::to_string(edit_count());
  for (Workload w : {Workload::kExplosion, Workload::kTunnel, Workload::kFill}) {
    const std::string name = std::string("game_edit/") + workload_name(w) + "/" + edits;
    benchmark::RegisterBenchmark(name.c_str(),
                                 [w](benchmark::State& state) { run_game_edit(state, w); })
        ->Iterations(1)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace edgeland::bench
