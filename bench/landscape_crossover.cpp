// The crossover (thesis chapter 5: "the same operation on a polygon-based landscape can
// actually be faster for very large areas at some point because the number of edges of a
// polygon is linear to the area it encloses"; the thesis did not measure where). One carve of a
// circle of radius R = 4 ... 4096 with game_sides(R) vertices (one per 8 units of
// circumference, 16 to 512), at CROSSOVER_REPS seeded centres (EDGELAND_LANDSCAPE_CROSSOVER_REPS,
// default 30) with the whole circle inside a 16384 x 16384 world of material 1, which is
//   caves: 4 x CAVES circles of radius 24-160 carved (the density of the query terrain), or
//   solid: untouched rock (the landscape's best case: one cell until the first edit).
//
// Every carve starts from the same terrain: the landscape carves a copy (O(1), untimed), the
// bitmap carves its array and gets the circle's box back from a second copy afterwards
// (untimed). Each carve's time is its fastest of REPEATS passes over all centres (a carve
// repeated at once would find its cells in the cache); reported is the median over the
// centres. Names landscape_crossover/TERRAIN/RIVAL/R; the landscape's median_vs_bitmap crosses 1
// at the crossover radius (run_landscape.sh interpolates it and plots both curves).
#include <map>
#include <optional>
#include <string>

#include "landscape_common.hpp"
#include "landscape_shapes.hpp"

namespace edgeland::bench {
namespace {

// EDGELAND_LANDSCAPE_CROSSOVER_SIDE (default 16384; the smoke test's is smaller, sparing it
// four 256 MiB bitmaps): radii up to a quarter of it are registered.
std::int64_t side() {
  return static_cast<std::int64_t>(env_count("EDGELAND_LANDSCAPE_CROSSOVER_SIDE", 16384));
}
Box64 world_box() { return {{0, 0}, {side(), side()}}; }

// The density of the query terrain: CAVES circles per 8192 x 8192 (4 x CAVES at 16384).
std::size_t cave_count() {
  const double scale = static_cast<double>(side()) / 8192.0;
  return static_cast<std::size_t>(static_cast<double>(env_count("EDGELAND_LANDSCAPE_CAVES", 300)) *
                                  scale * scale);
}

enum class Terrain : std::uint8_t { kCaves, kSolid };
const char* terrain_name(Terrain t) { return t == Terrain::kCaves ? "caves" : "solid"; }

const World& terrain(Terrain t, Rival rival) {
  static std::map<std::pair<Terrain, Rival>, World> cache;
  auto it = cache.find({t, rival});
  if (it == cache.end()) {
    World world = make_world(rival, world_box(), 1);
    const std::size_t count = t == Terrain::kCaves ? cave_count() : 0;
    for (const ValidSet& cave : as_shapes(caves(0xC405, count, world_box())))
      apply(world, EditKind::kCarve, cave, kEmpty);
    it = cache.emplace(std::make_pair(t, rival), std::move(world)).first;
  }
  return it->second;
}

std::vector<ValidSet> circles(std::int64_t radius) {
  const std::size_t n = env_count("EDGELAND_LANDSCAPE_CROSSOVER_REPS", 30);
  std::vector<Polygon> polygons;
  for (const Point64& c :
       random_points(0xC2055 + static_cast<std::uint64_t>(radius), n, inset(world_box(), radius)))
    polygons.push_back(
        ngon(c, static_cast<double>(radius), game_sides(static_cast<double>(radius))));
  return as_shapes(polygons);
}

// One carve from the terrain, timed: into a copy of the landscape (O(1)); into the bitmap's
// working array, whose circle box is then copied back from the terrain.
double carve_landscape(const Landscape& base, const ValidSet& shape) {
  Landscape copy = base;
  return seconds_of([&] { copy.carve(shape); });
}

double carve_bitmap(BitmapWorld& work, const BitmapWorld& base, const ValidSet& shape) {
  const double s = seconds_of([&] { work.carve(shape.polygons()); });
  work.restore(base, *bounding_box(shape.polygons()));
  return s;
}

std::vector<double> carve_times(Terrain t, Rival rival, const std::vector<ValidSet>& shapes) {
  const World& base = terrain(t, rival);
  const auto* landscape = std::get_if<Landscape>(&base);
  std::optional<BitmapWorld> work;
  if (landscape == nullptr) work.emplace(std::get<BitmapWorld>(base));
  std::vector<double> fastest(shapes.size());
  for (std::size_t r = 0; r < repeats(); ++r) {
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      const double s = landscape != nullptr
                           ? carve_landscape(*landscape, shapes[i])
                           : carve_bitmap(*work, std::get<BitmapWorld>(base), shapes[i]);
      fastest[i] = r == 0 ? s : std::min(fastest[i], s);
    }
  }
  return fastest;
}

// The bitmap's median per radius, from its own benchmark or made here.
std::map<std::pair<Terrain, std::int64_t>, double>& bitmap_medians() {
  static std::map<std::pair<Terrain, std::int64_t>, double> cache;
  return cache;
}

double bitmap_median_us(Terrain t, std::int64_t radius) {
  auto& cache = bitmap_medians();
  auto it = cache.find({t, radius});
  if (it == cache.end())
    it = cache
             .emplace(std::make_pair(t, radius),
                      quantile(carve_times(t, Rival::kBitmap, circles(radius)), 0.5) * 1e6)
             .first;
  return it->second;
}

void run_crossover_benchmark(benchmark::State& state, Terrain t, Rival rival) {
  const std::int64_t radius = state.range(0);
  std::vector<ValidSet> shapes;
  std::vector<double> seconds;
  for (auto _ : state) {
    if (!guarded(state, [&] {
          shapes = circles(radius);
          seconds = carve_times(t, rival, shapes);
        }))
      return;
    double total = 0;
    for (double s : seconds) total += s;
    state.SetIterationTime(total);
  }
  if (!verify(state, terrain(t, rival))) return;
  const double median_us = quantile(seconds, 0.5) * 1e6;
  state.counters["median_us"] = median_us;
  state.counters["p90_us"] = quantile(seconds, 0.9) * 1e6;
  state.counters["shape_vertices"] = static_cast<double>(shapes.front().polygons().front().size());
  if (rival == Rival::kBitmap) {
    bitmap_medians().insert_or_assign({t, radius}, median_us);
    return;
  }
  report_stats(state, terrain(t, rival));
  guarded(state,
          [&] { state.counters["median_vs_bitmap"] = median_us / bitmap_median_us(t, radius); });
}

}  // namespace

void register_crossover_benchmarks() {
  for (Terrain t : {Terrain::kCaves, Terrain::kSolid}) {
    for (Rival rival : {Rival::kBitmap, Rival::kQuadtree}) {
      auto* b = benchmark::RegisterBenchmark(
          (std::string("landscape_crossover/") + terrain_name(t) + "/" + rival_name(rival)).c_str(),
          [t, rival](benchmark::State& state) { run_crossover_benchmark(state, t, rival); });
      for (std::int64_t radius = 4; radius <= 4096 && 4 * radius <= side(); radius *= 2)
        b->Arg(radius);
      b->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace edgeland::bench
