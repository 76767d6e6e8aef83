// The one-shot workloads of issue 4 ("Speed"): one operation on two seeded operands, timed
// from the peer's input representation to its output representation (peer.hpp).
#include <benchmark/benchmark.h>

#include <exception>
#include <map>
#include <string>
#include <utility>

#include "registration.hpp"
#include "ring_check.hpp"
#include "workloads.hpp"

namespace edgeland::bench {
namespace {

struct Family {
  const char* name;
  ClipOp op;
  const char* generator_name;
  Operands (*generate)(std::size_t);
  std::vector<std::int64_t> sizes;
};

const std::vector<Family>& families() {
  static const std::vector<Family> kFamilies = {
      {"smooth_intersection",
       ClipOp::kIntersection,
       "smooth",
       smooth_stars,
       {100, 1000, 10000, 100000}},
      {"smooth_difference",
       ClipOp::kDifference,
       "smooth",
       smooth_stars,
       {100, 1000, 10000, 100000}},
      {"spiky_intersection", ClipOp::kIntersection, "spiky", spiky_stars, {100, 1000, 10000}},
      {"spiky_difference", ClipOp::kDifference, "spiky", spiky_stars, {100, 1000, 10000}},
      {"checkerboard_union",
       ClipOp::kUnion,
       "checkerboard",
       checkerboard,
       {100, 1000, 10000, 100000}},
  };
  return kFamilies;
}

// Inputs are generated once per (generator, size) and shared by every peer.
const Operands& operands(const Family& family, std::size_t n) {
  static std::map<std::pair<std::string, std::size_t>, Operands> cache;
  const auto key = std::make_pair(std::string(family.generator_name), n);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, family.generate(n)).first;
  return it->second;
}

std::size_t vertices(const PolygonSet& set) {
  std::size_t n = 0;
  for (const Polygon& p : set) n += p.size();
  return n;
}

void run(benchmark::State& state, const Peer& peer, const Family& family) {
  const Operands& in = operands(family, static_cast<std::size_t>(state.range(0)));
  const std::unique_ptr<Shape> subject = peer.load(in.subject);
  const std::unique_ptr<Shape> clip_shape = peer.load(in.clip);
  std::unique_ptr<Shape> result;
  for (auto _ : state) {
    try {
      result = peer.apply(family.op, *subject, *clip_shape);
    } catch (const std::exception& e) {
      state.SkipWithError((peer.name() + " threw: " + e.what()).c_str());
      break;
    }
  }
  if (!result) return;
  // Not timed: is the result, rounded back to integers, a valid edgeland input?
  const RingCheck check = check_rings(peer.rings(*result));
  if (!check.ok) state.SetLabel(peer.name() + " invalid result: " + check.failure);
  state.counters["valid"] = check.ok ? 1 : 0;
  state.counters["in_vertices"] = static_cast<double>(vertices(in.subject) + vertices(in.clip));
  state.counters["out_vertices"] = static_cast<double>(peer.vertex_count(*result));
  if (const std::size_t k = peer.intersections(*result); k > 0) {
    state.counters["intersections"] = static_cast<double>(k);
  }
}

}  // namespace

void register_clip_benchmarks(const std::vector<std::unique_ptr<Peer>>& peers) {
  for (const Family& family : families()) {
    for (const auto& peer : peers) {
      auto* b = benchmark::RegisterBenchmark(
          (std::string(family.name) + "/" + peer->name()).c_str(),
          [&family, p = peer.get()](benchmark::State& state) { run(state, *p, family); });
      for (const std::int64_t n : family.sizes) b->Arg(n);
      // Ratios use CPU time: the machine is shared and every peer is single-threaded.
      b->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace edgeland::bench
