// game_island/shelf/BITES: the worst debris frame a game meets, one big island falling at once
// (issue 35: a 335-polygon island cost 43-57 ms in one frame, 1,601 fixtures in its body).
// A 4096 x 4096 world: anchored bedrock below, a rock shelf of 2048 x 256 held by one pillar,
// the shelf's top and bottom bitten and its inside pocked by BITES small circles (radius 6-16 at
// seeded places), so that its outline is rough and its cells small: the island it becomes is many
// cells' polygons. One frame cuts the pillar; the frames after it are empty updates until the
// island has fallen (the driver makes a big island's debris in steps within
// GameOptions::debris_budget, then carves it out). Timed, in thread CPU time, fastest of
// EDGELAND_GAME_REPEATS (default 5) plays from the same start, summed over those frames:
//   game_update:    GameDriver::apply (the edit, chains, the island found, its debris steps:
//                   merged, cut into convex pieces, meshed; then detached);
//   terrain_update: box2d::Terrain::apply of each update;
//   debris_body:    box2d::make_debris_body of the island;
//   worst_frame:    the costliest of those frames (the benchmark's time), all_frames their sum.
// Counters: the island's polygons in the landscape before the cut (its cells' pieces), the
// merged outline's polygons and vertices, the body's fixtures, the frames it took.
#include <algorithm>
#include <span>
#include <string>

#include "edgeland/box2d/terrain.hpp"
#include "edgeland/kernel/shapes.hpp"
#include "edgeland/kernel/splitmix64.hpp"
#include "game_common.hpp"

namespace edgeland::bench {
namespace {

constexpr Material kBedrock = 1, kRock = 2;
constexpr Box64 kWorld{{0, 0}, {4096, 4096}};
constexpr Box64 kShelf{{1024, 2048}, {3072, 2304}};
constexpr Box64 kPillar{{2000, 1024}, {2096, 2048}};
constexpr Box64 kCut{{1980, 1500}, {2116, 1600}};

std::size_t bite_count() { return env_count("EDGELAND_ISLAND_BITES", 1200); }

// The shelf's edges bitten: circles centred on its top or bottom line, away from the pillar.
Landscape shelf_world(std::size_t bites) {
  Landscape world(kWorld);
  world.fill(PolygonSet{box_shape({{0, 0}, {4096, 1024}})}, kBedrock);
  world.fill(PolygonSet{box_shape(kPillar)}, kRock);
  world.fill(PolygonSet{box_shape(kShelf)}, kRock);
  SplitMix64 random(0x15'1A4D);
  const auto in = [&](std::int64_t lo, std::int64_t hi) {
    return lo + static_cast<std::int64_t>(random.next() % static_cast<std::uint64_t>(hi - lo + 1));
  };
  for (std::size_t i = 0; i < bites; ++i) {
    const std::int64_t y = i % 3 == 0   ? kShelf.max.y
                           : i % 3 == 1 ? kShelf.min.y
                                        : in(kShelf.min.y + 40, kShelf.max.y - 40);
    std::int64_t x = in(kShelf.min.x, kShelf.max.x);
    if (y == kShelf.min.y && x > kPillar.min.x - 24 && x < kPillar.max.x + 24) x += 160;
    world.carve(PolygonSet{circle({x, y + in(-8, 8)}, in(6, 16))});
  }
  return world;
}

GameOptions island_options() {
  GameOptions o;
  o.surface.materials.set_anchored(kBedrock);
  return o;
}

std::size_t polygons_in(const Landscape& world, const Box64& box) {
  std::size_t n = 0;
  world.polygons_in(box, [&](const PolygonView& v) {
    n += v.material == kRock && box.contains(*bounding_box(*v.polygon)) ? 1 : 0;
    return true;
  });
  return n;
}

enum Stage : std::size_t { kGame, kTerrain, kBody, kWorst, kTotal, kStageCount };
constexpr std::array<const char*, kStageCount> kStageNames{
    "game_update", "terrain_update", "debris_body", "worst_frame", "all_frames"};

struct Play {
  std::array<double, kStageCount> seconds{};
  std::size_t frames = 0, islands = 0, merged_polygons = 0, merged_vertices = 0, fixtures = 0;
};

void count_debris(const GameUpdate& u, Play& p) {
  p.islands += u.debris.size();
  for (const Debris& d : u.debris) {
    p.fixtures += d.pieces.size();
    for (const Debris::Region& r : d.regions)
      for (const Polygon& polygon : r.polygons) {
        ++p.merged_polygons;
        p.merged_vertices += polygon.size();
      }
  }
}

// The cut, then empty updates until the island has fallen (its debris made in steps within the
// driver's budget): every frame's game, terrain and body time, the worst frame and the sum.
Play play(const Landscape& start) {
  b2World world(b2Vec2(0, -10));
  GameDriver game(start, island_options());
  box2d::TerrainOptions options;
  options.units_per_metre = kUnitsPerMetre;
  box2d::Terrain terrain(world, game, options);
  terrain.apply(game.apply(std::span<const edgeland::Edit>{}));  // slivers the bites cut off
  while (game.debris_waiting() > 0) terrain.apply(game.apply(std::span<const edgeland::Edit>{}));
  Play p;
  const edgeland::Edit cut =
      edgeland::Edit::carve(ValidSet(PolygonSet{box_shape(kCut)}, Operand::kClip));
  for (bool first = true; first || game.debris_waiting() > 0; first = false) {
    ThreadClock clock;
    const GameUpdate u = first ? game.apply(cut) : game.apply(std::span<const edgeland::Edit>{});
    const double t_game = clock.lap();
    terrain.apply(u);
    const double t_terrain = clock.lap();
    for (const Debris& d : u.debris) box2d::make_debris_body(world, d, terrain.units());
    const double t_body = clock.lap();
    p.seconds[kGame] += t_game;
    p.seconds[kTerrain] += t_terrain;
    p.seconds[kBody] += t_body;
    p.seconds[kWorst] = std::max(p.seconds[kWorst], t_game + t_terrain + t_body);
    p.seconds[kTotal] += t_game + t_terrain + t_body;
    ++p.frames;
    count_debris(u, p);
  }
  return p;
}

void run_island(benchmark::State& state) {
  const Landscape start = shelf_world(bite_count());
  const std::size_t before = polygons_in(start, kShelf);
  Play best;
  best.seconds.fill(1e300);
  for (auto _ : state) {
    for (std::size_t r = 0; r < game_repeats(); ++r) {
      Play p;
      if (!guarded(state, [&] { p = play(start); })) return;
      if (p.islands != 1)
        return fail(state, "the cut detached " + std::to_string(p.islands) +
                               " islands, not the shelf alone");
      for (std::size_t k = 0; k < kStageCount; ++k)
        best.seconds[k] = std::min(best.seconds[k], p.seconds[k]);
      best.islands = p.islands;
      best.frames = p.frames;
      best.merged_polygons = p.merged_polygons;
      best.merged_vertices = p.merged_vertices;
      best.fixtures = p.fixtures;
    }
    state.SetIterationTime(best.seconds[kWorst]);
  }
  for (std::size_t k = 0; k < kStageCount; ++k)
    state.counters[std::string(kStageNames[k]) + "_us"] = best.seconds[k] * 1e6;
  state.counters["island_polygons"] = static_cast<double>(before);
  state.counters["merged_polygons"] = static_cast<double>(best.merged_polygons);
  state.counters["merged_vertices"] = static_cast<double>(best.merged_vertices);
  state.counters["fixtures"] = static_cast<double>(best.fixtures);
  state.counters["frames"] = static_cast<double>(best.frames);
}

}  // namespace

void register_island_benchmarks() {
  const std::string name = "game_island/shelf/" + std::to_string(bite_count());
  benchmark::RegisterBenchmark(name.c_str(), run_island)
      ->Iterations(1)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond);
}

}  // namespace edgeland::bench
