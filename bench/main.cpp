// edgeland_bench: edgeland's clipper against its peers, same seeded inputs, same run.
// See bench/README.md; run_ratios.sh turns the JSON output into the ratio table.
#include <benchmark/benchmark.h>

#include "registration.hpp"

int main(int argc, char** argv) {
  // Peers outlive every benchmark (GEOS shapes hold the peer's context).
  static const auto peers = edgeland::bench::make_all_peers();
  edgeland::bench::register_clip_benchmarks(peers);
  edgeland::bench::register_carving_benchmarks(peers);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
