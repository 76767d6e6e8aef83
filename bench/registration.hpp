#pragma once
// Benchmark families; each registers one benchmark per (peer, size) so that
// --benchmark_filter=/NAME/ selects one peer (run_ratios.sh runs peers in separate processes).
#include <memory>
#include <vector>

#include "peer.hpp"

namespace edgeland::bench {

// smooth_{intersection,difference}, spiky_{intersection,difference}, checkerboard_union:
// names FAMILY/PEER/SIZE.
void register_clip_benchmarks(const std::vector<std::unique_ptr<Peer>>& peers);

// carving/PEER/OPS, OPS from EDGELAND_BENCH_CARVE_OPS (default 10000).
void register_carving_benchmarks(const std::vector<std::unique_ptr<Peer>>& peers);

}  // namespace edgeland::bench
