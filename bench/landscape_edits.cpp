// Edits on an 8192 x 8192 world (thesis chapter 5: "small but continuous modifications", where
// the pixel landscape is expected to be unbeatable): per-edit median, p99 and the median of
// every block of edits (flat blocks = the cost does not grow as the world is worn down), for
// the landscape as quadtree, kd-tree and uniform grid, and for the bitmap. The workloads
// (carve, dig, fill, spot) are landscape_workloads.hpp's.
//
// Names landscape_edit/WORKLOAD/RIVAL/EDITS, EDITS from EDGELAND_LANDSCAPE_EDITS (default
// 10000), blocks of EDGELAND_LANDSCAPE_BLOCK (1000); each edit's time is its fastest of
// EDGELAND_LANDSCAPE_REPEATS runs from the same start (landscape_common.hpp). Every rival gets the
// same shapes as ValidSets built before any clock starts (the bitmap reads their polygons): neither
// side validates on the clock. Ratios against the bitmap (X_vs_bitmap = landscape time / bitmap
// time) come from the same process: the bitmap is registered first, and run here if it was filtered
// out.
#include <map>
#include <optional>
#include <string>

#include "landscape_common.hpp"
#include "landscape_workloads.hpp"

namespace edgeland::bench {
namespace {

std::size_t edit_count() { return env_count("EDGELAND_LANDSCAPE_EDITS", 10000); }

const std::vector<Edit>& edits(Workload w) {
  static std::map<Workload, std::vector<Edit>> cache;
  auto it = cache.find(w);
  if (it == cache.end()) it = cache.emplace(w, workload_edits(w, edit_count())).first;
  return it->second;
}

// The world each rival ends the carve workload with: the fill workload's start. Kept from the
// carve benchmark's own run (a landscape copy is O(1)), made here when that was filtered out.
std::map<Rival, World>& carved_worlds() {
  static std::map<Rival, World> cache;
  return cache;
}

World start_world(Workload w, Rival rival) {
  if (w != Workload::kFill) return make_world(rival, kEditWorld, 1);
  auto& cache = carved_worlds();
  auto it = cache.find(rival);
  if (it == cache.end()) {
    World world = make_world(rival, kEditWorld, 1);
    time_edits(world, edits(Workload::kCarve));
    it = cache.emplace(rival, std::move(world)).first;
  }
  return it->second;
}

struct RunResult {
  std::vector<double> seconds;
  std::optional<World> world;
};

RunResult run_once(Workload w, Rival rival) {
  RunResult r;
  r.seconds = fastest_edits(start_world(w, rival), edits(w), r.world);
  return r;
}

// The bitmap's summary of a workload, from its own benchmark or made here.
std::map<Workload, EditSummary>& bitmap_summaries() {
  static std::map<Workload, EditSummary> cache;
  return cache;
}

const EditSummary& bitmap_summary(Workload w, std::size_t block) {
  auto& cache = bitmap_summaries();
  auto it = cache.find(w);
  if (it == cache.end())
    it = cache.emplace(w, summarize(run_once(w, Rival::kBitmap).seconds, block)).first;
  return it->second;
}

void report_ratios(benchmark::State& state, const EditSummary& s, const EditSummary& bitmap) {
  state.counters["median_vs_bitmap"] = s.median_us / bitmap.median_us;
  state.counters["p99_vs_bitmap"] = s.p99_us / bitmap.p99_us;
  state.counters["mean_vs_bitmap"] = s.mean_us / bitmap.mean_us;
}

void run_edit_benchmark(benchmark::State& state, Workload w, Rival rival) {
  const std::size_t block = env_count("EDGELAND_LANDSCAPE_BLOCK", 1000);
  RunResult r;
  for (auto _ : state) {
    if (!guarded(state, [&] { r = run_once(w, rival); })) return;
    double total = 0;
    for (double s : r.seconds) total += s;
    state.SetIterationTime(total);
  }
  if (!verify(state, *r.world)) return;
  const EditSummary s = summarize(r.seconds, block);
  report(state, s);
  report_stats(state, *r.world);
  if (w == Workload::kCarve) carved_worlds().insert_or_assign(rival, *r.world);
  if (rival == Rival::kBitmap) {
    bitmap_summaries().insert_or_assign(w, s);
    return;
  }
  if (!guarded(state, [&] { report_ratios(state, s, bitmap_summary(w, block)); })) return;
}

}  // namespace

World carve_workload_end(Rival rival) { return start_world(Workload::kFill, rival); }

void register_edit_benchmarks() {
  const std::string edits = std::to_string(edit_count());
  for (Workload w : kWorkloads) {
    for (Rival rival : {Rival::kBitmap, Rival::kQuadtree, Rival::kKdTree, Rival::kGrid}) {
      const std::string name =
          std::string("landscape_edit/") + workload_name(w) + "/" + rival_name(rival) + "/" + edits;
      benchmark::RegisterBenchmark(
          name.c_str(),
          [w, rival](benchmark::State& state) { run_edit_benchmark(state, w, rival); })
          ->Iterations(1)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace edgeland::bench
