// Save and load of the world the carve workload leaves (landscape_edits.cpp: the 8192 x 8192
// world after its carves, caves split by bridges in many cells), alternated SAVE_LOADS times
// (EDGELAND_LANDSCAPE_SAVE_LOADS, default 20) so both see the same machine: the medians of each
// and load over save. A load validates everything it reads (spatial/README.md, "Save/load");
// issue 27, point 5 asked for it within about 5 times a save.
#include <sstream>

#include "landscape_common.hpp"

namespace edgeland::bench {
namespace {

void run_save_load_benchmark(benchmark::State& state) {
  std::vector<double> save_s, load_s;
  std::size_t file_bytes = 0;
  for (auto _ : state) {
    const World world = carve_workload_end(Rival::kQuadtree);
    const Landscape& live = std::get<Landscape>(world);
    const std::size_t n = env_count("EDGELAND_LANDSCAPE_SAVE_LOADS", 20);
    for (std::size_t i = 0; i < n; ++i) {
      std::ostringstream out;
      save_s.push_back(seconds_of([&] { live.save(out); }));
      const std::string bytes = out.str();
      file_bytes = bytes.size();
      std::istringstream in(bytes);
      std::optional<Landscape> back;
      load_s.push_back(seconds_of([&] { back.emplace(Landscape::load(in)); }));
      if (back->state_hash() != live.state_hash()) state.SkipWithError("load changed the state");
    }
    double total = 0;
    for (double s : load_s) total += s;
    state.SetIterationTime(total);
  }
  const double save_ms = quantile(save_s, 0.5) * 1e3, load_ms = quantile(load_s, 0.5) * 1e3;
  state.counters["file_bytes"] = static_cast<double>(file_bytes);
  state.counters["save_ms"] = save_ms;
  state.counters["load_ms"] = load_ms;
  state.counters["load_over_save"] = load_ms / save_ms;
}

}  // namespace

void register_save_load_benchmarks() {
  benchmark::RegisterBenchmark("landscape_save_load/quadtree", run_save_load_benchmark)
      ->Iterations(1)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond);
}

}  // namespace edgeland::bench
