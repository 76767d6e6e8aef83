// World-size scaling (thesis chapter 5: a pixel landscape's memory grows with its area, a
// polygon landscape's with its detail): worlds of side 1024, 4096, 16384 and 65536 filled with
// material 1 and worn down at the SAME DENSITY of edits per area: one 32-gon of radius 40 per
// EDGELAND_LANDSCAPE_SCALING_AREA square units (default 128 x 128 = 16384, about a quarter of
// the area carved), i.e. 64, 1,024, 16,384 and 262,144 edits. Same density rather than the
// same number of edits, because a fixed count either leaves the large worlds untouched or
// carves the small ones away completely, and neither is a game.
//
// All edits but the last TIMED (EDGELAND_LANDSCAPE_SCALING_TIMED, default 1000) are made
// untimed; the last ones are timed, each its fastest of REPEATS runs. Then material_at and a
// 200-unit raycast from empty space are timed at QUERIES random places, and the memory is
// reported: LandscapeStats::bytes (per vertex) against the bitmap's one byte per square.
// The bitmap runs up to 16384^2 (256 MiB); at 65536^2 it would take 4 GiB and is not built
// (its bytes are still reported: side^2).
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "landscape_common.hpp"
#include "landscape_shapes.hpp"

namespace edgeland::bench {
namespace {

constexpr std::int64_t kLargestBitmap = 16384;

Box64 world_of(std::int64_t side) { return {{0, 0}, {side, side}}; }

const std::vector<ValidSet>& edits(std::int64_t side) {
  static std::map<std::int64_t, std::vector<ValidSet>> cache;
  auto it = cache.find(side);
  if (it == cache.end()) {
    const double area = env_number("EDGELAND_LANDSCAPE_SCALING_AREA", 16384);
    const auto n =
        static_cast<std::size_t>(static_cast<double>(side) * static_cast<double>(side) / area);
    std::vector<Polygon> polygons;
    for (const Point64& c :
         random_points(0x5CA1E + static_cast<std::uint64_t>(side), n, world_of(side)))
      polygons.push_back(ngon(c, 40, 32));
    it = cache.emplace(side, as_shapes(polygons)).first;
  }
  return it->second;
}

struct Scaled {
  std::vector<double> edit_seconds;
  std::optional<World> world;
  std::vector<double> point_seconds, ray_seconds;
};

// Seeded rays of 200 units from points the reference landscape calls empty, both ends in the
// world; the same rays for both rivals of a size.
std::vector<std::pair<Point64, Point64>> rays(const World& reference, std::int64_t side,
                                              std::size_t n) {
  SplitMix64 random(0x5CA1E7 + static_cast<std::uint64_t>(side));
  std::vector<std::pair<Point64, Point64>> out;
  for (std::size_t tries = 0; out.size() < n && tries < 100 * n; ++tries) {
    const Point64 from = random_points(random.next(), 1, world_of(side)).front();
    const double angle = 2.0 * 3.14159265358979323846 * unit_draw(random);
    const Point64 to{from.x + std::llround(200 * std::cos(angle)),
                     from.y + std::llround(200 * std::sin(angle))};
    if (world_of(side).contains(to) && material_at(reference, from) == kEmpty)
      out.push_back({from, to});
  }
  return out;
}

void time_queries(Scaled& s, const World& reference, std::int64_t side) {
  const std::size_t n = env_count("EDGELAND_LANDSCAPE_QUERIES", 10000);
  const std::vector<Point64> points = random_points(0x5CA1E9, n, {{0, 0}, {side - 1, side - 1}});
  const auto ray_set = rays(reference, side, n);
  std::size_t sink = 0;
  std::visit(
      [&](const auto& w) {
        s.point_seconds = batch_seconds(
            points.size(), [&](std::size_t i) { sink += w.material_at(points[i]).value(); });
        s.ray_seconds = batch_seconds(ray_set.size(), [&](std::size_t i) {
          sink += w.raycast(ray_set[i].first, ray_set[i].second).has_value();
        });
      },
      *s.world);
  benchmark::DoNotOptimize(sink);
}

// The quadtree's end state of each size: the rays' reference (kept: a landscape copy is O(1)).
std::map<std::int64_t, World>& quadtree_worlds() {
  static std::map<std::int64_t, World> cache;
  return cache;
}

Scaled run_scaled(Rival rival, std::int64_t side) {
  const std::vector<ValidSet>& all = edits(side);
  const std::size_t timed =
      std::min(all.size(), env_count("EDGELAND_LANDSCAPE_SCALING_TIMED", 1000));
  World start = make_world(rival, world_of(side), 1);
  for (std::size_t i = 0; i + timed < all.size(); ++i)
    apply(start, EditKind::kCarve, all[i], kEmpty);
  const std::vector<ValidSet> last(all.end() - static_cast<std::ptrdiff_t>(timed), all.end());
  Scaled s;
  s.edit_seconds = fastest_edits(start, edits_of(EditKind::kCarve, last, kEmpty), s.world);
  if (rival == Rival::kQuadtree) quadtree_worlds().insert_or_assign(side, *s.world);
  auto it = quadtree_worlds().find(side);
  if (it == quadtree_worlds().end())
    it = quadtree_worlds().emplace(side, run_scaled(Rival::kQuadtree, side).world.value()).first;
  time_queries(s, it->second, side);
  return s;
}

struct ScaledSummary {
  double edit_median_us, edit_p99_us, material_at_ns, raycast_ns;
};

ScaledSummary summary_of(const Scaled& s) {
  return {quantile(s.edit_seconds, 0.5) * 1e6, quantile(s.edit_seconds, 0.99) * 1e6,
          quantile(s.point_seconds, 0.5) * 1e9, quantile(s.ray_seconds, 0.5) * 1e9};
}

const ScaledSummary& bitmap_summary(std::int64_t side) {
  static std::map<std::int64_t, ScaledSummary> cache;
  auto it = cache.find(side);
  if (it == cache.end())
    it = cache.emplace(side, summary_of(run_scaled(Rival::kBitmap, side))).first;
  return it->second;
}

void report_scaled(benchmark::State& state, const ScaledSummary& m, std::int64_t side) {
  state.counters["edit_median_us"] = m.edit_median_us;
  state.counters["edit_p99_us"] = m.edit_p99_us;
  state.counters["material_at_ns"] = m.material_at_ns;
  state.counters["raycast_ns"] = m.raycast_ns;
  state.counters["bitmap_bytes"] = static_cast<double>(side) * static_cast<double>(side);
}

void report_against_bitmap(benchmark::State& state, const ScaledSummary& m, std::int64_t side) {
  state.counters["bytes_vs_bitmap"] = state.counters["bytes"] / state.counters["bitmap_bytes"];
  if (side > kLargestBitmap) return;
  const ScaledSummary& b = bitmap_summary(side);
  state.counters["edit_median_vs_bitmap"] = m.edit_median_us / b.edit_median_us;
  state.counters["edit_p99_vs_bitmap"] = m.edit_p99_us / b.edit_p99_us;
  state.counters["material_at_vs_bitmap"] = m.material_at_ns / b.material_at_ns;
  state.counters["raycast_vs_bitmap"] = m.raycast_ns / b.raycast_ns;
}

void run_scaling_benchmark(benchmark::State& state, Rival rival) {
  const std::int64_t side = state.range(0);
  Scaled s;
  for (auto _ : state) {
    if (!guarded(state, [&] { s = run_scaled(rival, side); })) return;
    double total = 0;
    for (double t : s.edit_seconds) total += t;
    state.SetIterationTime(total);
  }
  if (!verify(state, *s.world)) return;
  const ScaledSummary m = summary_of(s);
  report_scaled(state, m, side);
  report_stats(state, *s.world);
  state.counters["edits"] = static_cast<double>(edits(side).size());
  state.counters["timed_edits"] = static_cast<double>(s.edit_seconds.size());
  if (rival != Rival::kBitmap) guarded(state, [&] { report_against_bitmap(state, m, side); });
}

}  // namespace

void register_scaling_benchmarks() {
  // The quadtree first: its end state is the rays' reference of both rivals, and the bitmap's
  // summary (for the ratios) is cheap to make on demand.
  for (Rival rival : {Rival::kQuadtree, Rival::kBitmap}) {
    auto* b = benchmark::RegisterBenchmark(
        (std::string("landscape_scaling/") + rival_name(rival)).c_str(),
        [rival](benchmark::State& state) { run_scaling_benchmark(state, rival); });
    for (std::int64_t side : {1024, 4096, 16384, 65536})
      if (rival != Rival::kBitmap || side <= kLargestBitmap) b->Arg(side);
    b->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
  }
}

}  // namespace edgeland::bench
