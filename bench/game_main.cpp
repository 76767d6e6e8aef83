// edgeland_game_bench: the game layer (game/, adapters/box2d) against the pixel pipeline a game
// would otherwise run, per edit and for a whole world (issue 26, "Speed"). See bench/README.md,
// "Game layer"; run_game.sh runs it and prints the tables.
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>

#include "game_common.hpp"

int main(int argc, char** argv) {
  cv::setNumThreads(1);  // every stage single-threaded on both sides, as the timing assumes
  edgeland::bench::register_game_edit_benchmarks();
  edgeland::bench::register_game_export_benchmarks();
  edgeland::bench::register_frame_benchmarks();
  edgeland::bench::register_island_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
