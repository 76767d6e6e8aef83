// Snapshots (rewind, replays, undo, a save on another thread): take a copy of the live world,
// then carve one 32-gon of radius 40 into the live world, SNAPSHOTS times
// (EDGELAND_LANDSCAPE_SNAPSHOTS, default 50), on the 8192 x 8192 world the carve workload
// leaves (landscape_edits.cpp). The landscape's copy shares its whole tree (O(1)); the carve
// then copies only the cells it changes and the path above them. The bitmap copies its 64 MiB:
// into a new array (copy_us, what `World snapshot = live;` costs) and, separately, into an
// existing one of the same size (copy_reuse_us: a ring of preallocated snapshots, no page
// faults; on this project's VM a page fault costs ~20 us, so the fresh copy is mostly faults).
// Reported: the medians of copy, carve and copy + carve, and the landscape's copy + carve over
// the bitmap's, with either kind of copy. Each copy and carve is timed once: repeating a carve
// at once would time it with its cells already in the cache.
#include <map>
#include <optional>
#include <string>

#include "landscape_common.hpp"
#include "landscape_shapes.hpp"

namespace edgeland::bench {
namespace {

constexpr Box64 kWorld{{0, 0}, {8192, 8192}};

struct SnapshotTimes {
  std::vector<double> copy, copy_reuse, carve, total, total_reuse;
  std::optional<World> end;  // the live world after the last carve
};

SnapshotTimes run_snapshots(Rival rival) {
  const std::size_t n = env_count("EDGELAND_LANDSCAPE_SNAPSHOTS", 50);
  std::vector<Polygon> polygons;
  for (const Point64& c : random_points(0x5A4B, n, kWorld)) polygons.push_back(ngon(c, 40, 32));
  const std::vector<ValidSet> shapes = as_shapes(polygons);
  World live = carve_workload_end(rival);
  std::optional<World> reused;
  if (!is_landscape(live)) reused.emplace(live);
  SnapshotTimes t;
  for (const ValidSet& shape : shapes) {
    std::optional<World> snapshot;
    t.copy.push_back(seconds_of([&] { snapshot.emplace(live); }));
    if (reused) t.copy_reuse.push_back(seconds_of([&] { *reused = live; }));
    t.carve.push_back(seconds_of([&] { apply(live, EditKind::kCarve, shape, kEmpty); }));
    t.total.push_back(t.copy.back() + t.carve.back());
    if (reused) t.total_reuse.push_back(t.copy_reuse.back() + t.carve.back());
  }
  t.end.emplace(std::move(live));
  return t;
}

// The bitmap's medians of copy + carve (fresh copy, reused array), from its own benchmark or
// made here.
std::optional<std::pair<double, double>>& bitmap_totals() {
  static std::optional<std::pair<double, double>> cache;
  return cache;
}

std::pair<double, double> totals_us(const SnapshotTimes& t) {
  return {quantile(t.total, 0.5) * 1e6, quantile(t.total_reuse, 0.5) * 1e6};
}

std::pair<double, double> bitmap_totals_us() {
  if (!bitmap_totals()) bitmap_totals() = totals_us(run_snapshots(Rival::kBitmap));
  return *bitmap_totals();
}

void run_snapshot_benchmark(benchmark::State& state, Rival rival) {
  SnapshotTimes t;
  for (auto _ : state) {
    if (!guarded(state, [&] { t = run_snapshots(rival); })) return;
    double total = 0;
    for (double s : t.total) total += s;
    state.SetIterationTime(total);
  }
  if (!verify(state, *t.end)) return;
  const double total_us = quantile(t.total, 0.5) * 1e6;
  state.counters["copy_us"] = quantile(t.copy, 0.5) * 1e6;
  state.counters["carve_us"] = quantile(t.carve, 0.5) * 1e6;
  state.counters["copy_and_carve_us"] = total_us;
  if (rival == Rival::kBitmap) {
    state.counters["copy_reuse_us"] = quantile(t.copy_reuse, 0.5) * 1e6;
    state.counters["copy_reuse_and_carve_us"] = quantile(t.total_reuse, 0.5) * 1e6;
    bitmap_totals() = totals_us(t);
    return;
  }
  guarded(state, [&] {
    const auto [fresh, reuse] = bitmap_totals_us();
    state.counters["copy_and_carve_vs_bitmap"] = total_us / fresh;
    state.counters["copy_and_carve_vs_bitmap_reuse"] = total_us / reuse;
  });
}

}  // namespace

void register_snapshot_benchmarks() {
  // The landscape first: run after the bitmap's thousands of megabytes of copies its carves
  // measured twice as slow (203 against 97 us) in one full run; alone, or first, they do not.
  for (Rival rival : {Rival::kQuadtree, Rival::kBitmap}) {
    benchmark::RegisterBenchmark(
        (std::string("landscape_snapshot/") + rival_name(rival)).c_str(),
        [rival](benchmark::State& state) { run_snapshot_benchmark(state, rival); })
        ->Iterations(1)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace edgeland::bench
