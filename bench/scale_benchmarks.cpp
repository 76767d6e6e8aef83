// edgeland_scale_bench (issue 16, point 1): one difference on large operands with many
// crossings, for edgeland and its peers, timed like clip_benchmarks.cpp (apply() only) and
// with the process's peak resident memory. Names are SHAPE/PEER/SIZE, SIZE the nominal
// vertex count per operand; run_scale.sh runs each in its own process under a time limit, so
// the peak is that peer's on that input.
//
// Counters: rss_before_mb is the process's peak resident set (getrusage ru_maxrss) just before
// apply(), with the inputs generated, validated and loaded into the peer's representation;
// rss_peak_mb the same right after apply(), before the result is checked. The edgeland copy
// of the operands is freed before apply(), so the peak is the peer's input, its working
// memory and its result (or the input phase, if that was higher).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "peer.hpp"
#include "ring_check.hpp"
#include "scale_workloads.hpp"

namespace edgeland::bench {
namespace {

struct ScaleShape {
  const char* name;
  Operands (*generate)(std::size_t vertices);
  std::vector<std::int64_t> sizes;
};

// T = n/4 teeth, so each comb has n + 2 vertices.
Operands short_combs(std::size_t n) { return combs(n / 4, 100'000, 1'000); }
Operands long_combs(std::size_t n) { return combs(n / 4, 100'000'000, 1'000'000); }

const std::vector<ScaleShape>& shapes() {
  static const std::vector<ScaleShape> kShapes = {
      {"comb_short", short_combs, {100'000, 1'000'000}},
      {"comb_long", long_combs, {100'000, 1'000'000}},
      {"zigzag", zigzag_stars, {100'000, 200'000, 1'000'000}},
      {"minus_empty", star_minus_empty, {100'000, 400'000}},
  };
  return kShapes;
}

// The process's peak resident set so far (Linux reports ru_maxrss in KiB).
double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

std::size_t vertices(const PolygonSet& set) {
  std::size_t n = 0;
  for (const Polygon& p : set) n += p.size();
  return n;
}

struct Loaded {
  std::unique_ptr<Shape> subject;
  std::unique_ptr<Shape> clip;
  std::size_t in_vertices = 0;
};

// Generates and loads the operands; the edgeland copies die here, before anything is timed.
Loaded load(const Peer& peer, const ScaleShape& shape, std::size_t n) {
  const Operands in = shape.generate(n);
  return {peer.load(in.subject), peer.load(in.clip), vertices(in.subject) + vertices(in.clip)};
}

// Not timed, and after the peak was read: the result, rounded to integers, is it valid?
void report_result(benchmark::State& state, const Peer& peer, const Shape& result) {
  const RingCheck check = check_rings(peer.rings(result));
  if (!check.ok) state.SetLabel(peer.name() + " invalid result: " + check.failure);
  state.counters["valid"] = check.ok ? 1 : 0;
  state.counters["out_vertices"] = static_cast<double>(peer.vertex_count(result));
  if (const std::size_t k = peer.intersections(result); k > 0) {
    state.counters["intersections"] = static_cast<double>(k);
  }
}

void run(benchmark::State& state, const Peer& peer, const ScaleShape& shape) {
  const Loaded in = load(peer, shape, static_cast<std::size_t>(state.range(0)));
  state.counters["in_vertices"] = static_cast<double>(in.in_vertices);
  state.counters["rss_before_mb"] = peak_rss_mb();
  std::unique_ptr<Shape> result;
  for (auto _ : state) {
    try {
      result = peer.apply(ClipOp::kDifference, *in.subject, *in.clip);
    } catch (const std::exception& e) {
      state.SkipWithError((peer.name() + " threw: " + e.what()).c_str());
      break;
    }
  }
  state.counters["rss_peak_mb"] = peak_rss_mb();
  if (result) report_result(state, peer, *result);
}

// edgeland first; the peers of issue 16 (CGAL and Boost double are left out: too slow at
// this scale in the issue 4 runs, and their builds are the slow ones).
std::vector<std::unique_ptr<Peer>> scale_peers() {
  std::vector<std::unique_ptr<Peer>> peers;
  peers.push_back(make_edgeland_peer());
  peers.push_back(make_edgeland_valid_peer());
  peers.push_back(make_geos_peer());
  peers.push_back(make_clipper1_peer());
  peers.push_back(make_boost_int64_peer());
  return peers;
}

void register_scale_benchmarks(const std::vector<std::unique_ptr<Peer>>& peers) {
  for (const ScaleShape& shape : shapes()) {
    for (const auto& peer : peers) {
      auto* b = benchmark::RegisterBenchmark(
          (std::string(shape.name) + "/" + peer->name()).c_str(),
          [&shape, p = peer.get()](benchmark::State& state) { run(state, *p, shape); });
      for (const std::int64_t n : shape.sizes) b->Arg(n);
      // One run: the large cases take seconds to minutes, and a second result alive beside
      // the first would blur the peak memory.
      b->Iterations(1)->Unit(benchmark::kSecond);
    }
  }
}

}  // namespace
}  // namespace edgeland::bench

int main(int argc, char** argv) {
  // Peers outlive every benchmark (GEOS shapes hold the peer's context).
  static const auto peers = edgeland::bench::scale_peers();
  edgeland::bench::register_scale_benchmarks(peers);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
