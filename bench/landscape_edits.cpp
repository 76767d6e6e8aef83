// Edits on an 8192 x 8192 world (thesis chapter 5: "small but continuous modifications", where
// the pixel landscape is expected to be unbeatable): per-edit median, p99 and the median of
// every block of edits (flat blocks = the cost does not grow as the world is worn down), for
// the landscape as quadtree, kd-tree and uniform grid, and for the bitmap. The workloads
// (carve, dig, fill, spot) are landscape_workloads.hpp's.
//
// Names landscape_edit/WORKLOAD/RIVAL/EDITS, and landscape_batch/WORKLOAD/RIVAL/EDITS/3 for the
// workloads at one place (dig, spot, pit, hotspot) in frame batches of 3 (times per batch: the
// landscape's apply_batch against the bitmap painting the same three); EDITS from
// EDGELAND_LANDSCAPE_EDITS (default 10000), blocks of EDGELAND_LANDSCAPE_BLOCK (1000); each edit's
// time is its fastest of EDGELAND_LANDSCAPE_REPEATS runs from the same start
// (landscape_common.hpp). Every rival gets the same shapes as ValidSets built before any clock
// starts (the bitmap reads their polygons): neither side validates on the clock. Ratios against the
// bitmap (X_vs_bitmap = landscape time / bitmap time) come from the same process: the bitmap is
// registered first, and run here if it was filtered out.
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

// Frame batches of this many edits (Landscape::apply_batch) in the landscape_batch rows.
constexpr std::size_t kBatchSize = 3;

RunResult run_once(Workload w, Rival rival, std::size_t batch) {
  RunResult r;
  r.seconds = fastest_edits(start_world(w, rival), edits(w), r.world, batch);
  return r;
}

// The bitmap's summary of a workload in batches of a size, from its own benchmark or made here.
using BitmapKey = std::pair<Workload, std::size_t>;
std::map<BitmapKey, EditSummary>& bitmap_summaries() {
  static std::map<BitmapKey, EditSummary> cache;
  return cache;
}

const EditSummary& bitmap_summary(Workload w, std::size_t batch, std::size_t block) {
  auto& cache = bitmap_summaries();
  auto it = cache.find({w, batch});
  if (it == cache.end())
    it = cache
             .emplace(BitmapKey{w, batch},
                      summarize(run_once(w, Rival::kBitmap, batch).seconds, block))
             .first;
  return it->second;
}

void report_ratios(benchmark::State& state, const EditSummary& s, const EditSummary& bitmap) {
  state.counters["median_vs_bitmap"] = s.median_us / bitmap.median_us;
  state.counters["p99_vs_bitmap"] = s.p99_us / bitmap.p99_us;
  state.counters["mean_vs_bitmap"] = s.mean_us / bitmap.mean_us;
}

void run_edit_benchmark(benchmark::State& state, Workload w, Rival rival, std::size_t batch) {
  const std::size_t block = env_count("EDGELAND_LANDSCAPE_BLOCK", 1000) / batch;
  RunResult r;
  for (auto _ : state) {
    if (!guarded(state, [&] { r = run_once(w, rival, batch); })) return;
    double total = 0;
    for (double s : r.seconds) total += s;
    state.SetIterationTime(total);
  }
  if (!verify(state, *r.world)) return;
  const EditSummary s = summarize(r.seconds, block);
  report(state, s);
  report_stats(state, *r.world);
  if (w == Workload::kCarve && batch == 1) carved_worlds().insert_or_assign(rival, *r.world);
  if (rival == Rival::kBitmap) {
    bitmap_summaries().insert_or_assign({w, batch}, s);
    return;
  }
  if (!guarded(state, [&] { report_ratios(state, s, bitmap_summary(w, batch, block)); })) return;
}

void register_edit_benchmark(const std::string& name, Workload w, Rival rival, std::size_t batch) {
  benchmark::RegisterBenchmark(
      name.c_str(),
      [w, rival, batch](benchmark::State& state) { run_edit_benchmark(state, w, rival, batch); })
      ->Iterations(1)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond);
}

}  // namespace

World carve_workload_end(Rival rival) { return start_world(Workload::kFill, rival); }

void register_edit_benchmarks() {
  const std::string edits = std::to_string(edit_count());
  for (Workload w : kWorkloads) {
    for (Rival rival : {Rival::kBitmap, Rival::kQuadtree, Rival::kKdTree, Rival::kGrid})
      register_edit_benchmark(
          std::string("landscape_edit/") + workload_name(w) + "/" + rival_name(rival) + "/" + edits,
          w, rival, 1);
  }
  // Frame batches where a game edits one place several times a frame: times per batch.
  for (Workload w : {Workload::kDig, Workload::kSpot, Workload::kPit, Workload::kHotSpot})
    for (Rival rival : {Rival::kBitmap, Rival::kQuadtree})
      register_edit_benchmark(std::string("landscape_batch/") + workload_name(w) + "/" +
                                  rival_name(rival) + "/" + edits + "/" +
                                  std::to_string(kBatchSize),
                              w, rival, kBatchSize);
}

}  // namespace edgeland::bench
