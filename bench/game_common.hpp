#pragma once
// What the game-layer benchmarks share (bench/README.md, "Game layer"): their sizes from the
// environment, the Box2D scale, per-edit series and their summaries as counters.
#include <benchmark/benchmark.h>
#include <time.h>

#include <cstddef>
#include <string>
#include <vector>

#include "landscape_common.hpp"

namespace edgeland::bench {

// Landscape units (bitmap squares) per Box2D metre, for edgeland's terrain and the pixel
// pipeline alike: an 8192-unit world is 256 m wide, and a unit (1/32 m) is above Box2D's
// linear slop (0.005 m), as adapters/README.md asks.
inline constexpr double kUnitsPerMetre = 32;

// EDGELAND_GAME_REPEATS (default 5): each timed run is repeated from the same start and every
// edit keeps its fastest time per stage (landscape_common.hpp, fastest_edits).
std::size_t game_repeats();

// The per-edit seconds of one stage, over the repeats: the fastest of each edit, and the median
// of each repeat (how much the machine moved between repeats).
struct Series {
  std::vector<double> fastest;
  std::vector<double> repeat_median;
  void add_repeat(const std::vector<double>& seconds);
};

// Sets NAME_median_us, NAME_p99_us, NAME_mean_us and NAME_max_us of the fastest times.
void report_series(benchmark::State& state, const std::string& name, const Series& s);

// This thread's CPU time: the machine is shared, and both sides are single-threaded.
class ThreadClock {
 public:
  ThreadClock() : last_(now()) {}
  double lap() {
    const double t = now();
    const double s = t - last_;
    last_ = t;
    return s;
  }

 private:
  static double now() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
  }
  double last_;
};

// Registration of each family: game_edit/WORKLOAD/EDITS (game_edits.cpp) and
// game_export/demo/EDITS (game_export.cpp).
void register_game_edit_benchmarks();
void register_game_export_benchmarks();
// game_frame/new_user/FRAMES (frame_benchmark.cpp).
void register_frame_benchmarks();
// game_island/shelf/BITES (game_island.cpp).
void register_island_benchmarks();

}  // namespace edgeland::bench
