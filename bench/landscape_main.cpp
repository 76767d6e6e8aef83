// edgeland_landscape_bench: the landscape against the pixel world it is meant to replace
// (thesis chapter 5, "when do polygons beat pixels?"). See bench/README.md, "Landscape";
// run_landscape.sh runs it and turns the JSON into the tables and the crossover plot.
#include <benchmark/benchmark.h>

#include "landscape_common.hpp"

int main(int argc, char** argv) {
  edgeland::bench::register_edit_benchmarks();
  edgeland::bench::register_query_benchmarks();
  edgeland::bench::register_scaling_benchmarks();
  edgeland::bench::register_crossover_benchmarks();
  edgeland::bench::register_snapshot_benchmarks();
  edgeland::bench::register_save_load_benchmarks();
  edgeland::bench::register_big_shape_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
