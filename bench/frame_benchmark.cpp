// game_frame/new_user/FRAMES: the frame-based game of frame_game.hpp, played
// EDGELAND_GAME_REPEATS times (default 3; which side runs first in a frame alternates between
// plays), every frame keeping its fastest time per stage (the game is deterministic: every play
// does the same frames, which the state hashes confirm). FRAMES from EDGELAND_FRAME_FRAMES
// (default 3000). Counters: each stage's median, p99, max and mean per frame; the end-to-end
// ratios (edgeland / pixel) at the median and p99; the worst frame of library work.
#include <string>

#include "frame_game.hpp"
#include "game_common.hpp"

namespace edgeland::bench {
namespace {

FrameGameOptions frame_options() {
  FrameGameOptions o;
  o.frames = env_count("EDGELAND_FRAME_FRAMES", o.frames);
  return o;
}

std::size_t frame_repeats() {
  return std::max<std::size_t>(1, env_count("EDGELAND_GAME_REPEATS", 3));
}

void report_run(benchmark::State& state, const FrameGameRun& run) {
  const double frames = static_cast<double>(run.seconds[kFrameEdgeland].size());
  state.counters["edits_per_frame"] = static_cast<double>(run.edits) / frames;
  state.counters["detached"] = static_cast<double>(run.detached);
  state.counters["buried"] = static_cast<double>(run.buried);
  state.counters["debris_fixtures_max"] = static_cast<double>(run.debris_fixtures_max);
  state.counters["debris_polygons_max"] = static_cast<double>(run.debris_polygons_max);
  state.counters["terrain_fixtures"] = static_cast<double>(run.terrain_fixtures);
  state.counters["pixel_fixtures"] = static_cast<double>(run.pixel_fixtures);
}

void report_ratios(benchmark::State& state, const std::array<Series, kFrameStageCount>& s) {
  const auto at = [&](FrameStage k, double q) { return quantile(s[k].fastest, q); };
  state.counters["median_ratio"] = at(kFrameEdgeland, 0.5) / at(kFramePixel, 0.5);
  state.counters["p99_ratio"] = at(kFrameEdgeland, 0.99) / at(kFramePixel, 0.99);
  double lo = 1e300, hi = 0;
  for (std::size_t r = 0; r < s[kFrameEdgeland].repeat_median.size(); ++r) {
    const double ratio = s[kFrameEdgeland].repeat_median[r] / s[kFramePixel].repeat_median[r];
    lo = std::min(lo, ratio);
    hi = std::max(hi, ratio);
  }
  state.counters["repeat_median_ratio_min"] = lo;
  state.counters["repeat_median_ratio_max"] = hi;
}

void run_frame_game(benchmark::State& state) {
  std::array<Series, kFrameStageCount> series;
  FrameGameRun first;
  for (auto _ : state) {
    for (std::size_t r = 0; r < frame_repeats(); ++r) {
      FrameGameRun run;
      if (!guarded(state, [&] { run = play_frame_game(frame_options(), r % 2 == 0); })) return;
      if (!run.landscape_ok) return fail(state, "landscape check failed: the frame game's world");
      if (r > 0 && run.state_hash != first.state_hash)
        return fail(state, "landscape threw: the plays differ (the game is not deterministic)");
      for (std::size_t k = 0; k < kFrameStageCount; ++k) series[k].add_repeat(run.seconds[k]);
      if (r == 0) first = std::move(run);
    }
    double total = 0;
    for (double s : series[kFrameEdgeland].fastest) total += s;
    state.SetIterationTime(total);
  }
  for (std::size_t k = 0; k < kFrameStageCount; ++k)
    report_series(state, kFrameStageNames[k], series[k]);
  report_ratios(state, series);
  report_run(state, first);
}

}  // namespace

void register_frame_benchmarks() {
  const std::string name = "game_frame/new_user/" + std::to_string(frame_options().frames);
  benchmark::RegisterBenchmark(name.c_str(), run_frame_game)
      ->Iterations(1)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond);
}

}  // namespace edgeland::bench
