// The carving workload of issue 4: an 8192 x 8192 square minus OPS 32-gons of radius 40, one
// difference at a time on the whole set, each result being the next subject (the naive
// landscape, before the spatial tree). For every peer: the mean time per operation over each
// block of operations as the set grows, and the first operation whose result, rounded back to
// integers, fails check_rings (ring_check.hpp).
//
// Environment: EDGELAND_BENCH_CARVE_OPS (default 10000) operations;
// EDGELAND_BENCH_CARVE_BLOCK (default 1000) operations per reported block;
// EDGELAND_BENCH_CARVE_BUDGET_S (default 0 = none) stops a peer once its run, operations and
// checks together, has taken that many wall-clock seconds (the counters then say how far it
// got). Wall clock, so that a busy machine cannot stretch a run past any outer timeout; it
// only decides how many operations run, never the per-operation times.
// The reported time is the sum of the timed operations only (manual time, measured as thread
// CPU time like the other families): loading each 32-gon and checking each result are not timed.
#include <benchmark/benchmark.h>
#include <time.h>

#include <chrono>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "registration.hpp"
#include "ring_check.hpp"
#include "workloads.hpp"

namespace edgeland::bench {
namespace {

double env_number(const char* name, double fallback) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return fallback;
  return std::strtod(value, nullptr);
}

const Carving& carving_input(std::size_t ops) {
  static Carving cached;
  if (cached.holes.size() != ops) cached = carving(ops);
  return cached;
}

// Two-digit block names keep the counters in order in every output format.
std::string block_name(std::size_t block, const char* what) {
  return std::string("block") + (block < 10 ? "0" : "") + std::to_string(block) + "_" + what;
}

// CPU time of this thread: the machine is shared, and every peer is single-threaded.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

// What one peer's run measured and found, reported as the benchmark's counters.
struct CarvingRun {
  std::vector<double> block_seconds;
  std::vector<std::size_t> block_vertices;
  std::size_t done = 0;
  std::int64_t first_invalid = -1;
  std::int64_t first_invalid_lenient = -1;  // repeated vertices merged first
  std::int64_t threw_at = -1;
  std::string note;
  double total = 0;
  double in_block = 0;

  // One timed operation done; every `block` of them closes a block.
  void count(double seconds, std::size_t block, const Peer& peer, const Shape& subject) {
    total += seconds;
    in_block += seconds;
    ++done;
    if (done % block == 0) close_block(block, peer, subject);
  }
  // The mean time per operation of the block (a last one may be partial) and the set's size.
  void close_block(std::size_t block, const Peer& peer, const Shape& subject) {
    block_seconds.push_back(in_block / static_cast<double>((done - 1) % block + 1));
    block_vertices.push_back(peer.vertex_count(subject));
    in_block = 0;
  }
  // Checked until the first failure of the lenient check; an invalid result is still fed on,
  // as a game would.
  void check(std::size_t op, const Peer& peer, const Shape& subject) {
    if (first_invalid_lenient >= 0) return;
    const PeerRings rings = peer.rings(subject);
    if (first_invalid < 0) {
      const RingCheck strict = check_rings(rings);
      if (strict.ok) return;
      first_invalid = static_cast<std::int64_t>(op);
      note = peer.name() + " op " + std::to_string(op) + " invalid: " + strict.failure;
    }
    const RingCheck lenient = check_rings(without_repeated_vertices(rings));
    if (lenient.ok) return;
    first_invalid_lenient = static_cast<std::int64_t>(op);
    if (first_invalid_lenient != first_invalid) {
      note += "; op " + std::to_string(op) +
              " invalid with repeated vertices merged: " + lenient.failure;
    }
  }
  void report(benchmark::State& state, std::size_t block) const {
    for (std::size_t b = 0; b < block_seconds.size(); ++b) {
      state.counters[block_name(b, "ms_per_op")] = block_seconds[b] * 1e3;
      state.counters[block_name(b, "vertices")] = static_cast<double>(block_vertices[b]);
    }
    state.counters["ops_done"] = static_cast<double>(done);
    state.counters["first_invalid_op"] = static_cast<double>(first_invalid);
    state.counters["first_invalid_op_lenient"] = static_cast<double>(first_invalid_lenient);
    state.counters["threw_at_op"] = static_cast<double>(threw_at);
    state.counters["block_size"] = static_cast<double>(block);
    if (!note.empty()) state.SetLabel(note);
  }
};

// The operations of one run, each result the next subject, until the last, a throw or the
// budget (wall-clock seconds since `start`; 0: none).
void carve_all(const Peer& peer, const Carving& work, std::size_t block, double budget,
               CarvingRun& run) {
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<Shape> subject = peer.load({work.square});
  for (std::size_t i = 0; i < work.holes.size(); ++i) {
    const std::unique_ptr<Shape> hole = peer.load({work.holes[i]});
    std::unique_ptr<Shape> next;
    const double op_start = thread_seconds();
    try {
      next = peer.apply(ClipOp::kDifference, *subject, *hole);
    } catch (const std::exception& e) {
      run.threw_at = static_cast<std::int64_t>(i + 1);
      run.note = peer.name() + " op " + std::to_string(i + 1) + " threw: " + e.what();
      break;
    }
    const double seconds = thread_seconds() - op_start;
    subject = std::move(next);
    run.count(seconds, block, peer, *subject);
    run.check(i + 1, peer, *subject);
    const std::chrono::duration<double> spent = std::chrono::steady_clock::now() - start;
    if (budget > 0 && spent.count() > budget) break;
  }
  if (run.done % block != 0) run.close_block(block, peer, *subject);  // a last, partial block
}

void run_carving(benchmark::State& state, const Peer& peer) {
  const auto ops = static_cast<std::size_t>(state.range(0));
  const auto block = static_cast<std::size_t>(env_number("EDGELAND_BENCH_CARVE_BLOCK", 1000));
  const double budget = env_number("EDGELAND_BENCH_CARVE_BUDGET_S", 0);
  const Carving& work = carving_input(ops);
  CarvingRun run;
  for (auto _ : state) {
    carve_all(peer, work, block, budget, run);
    state.SetIterationTime(run.total);
  }
  run.report(state, block);
}

}  // namespace

void register_carving_benchmarks(const std::vector<std::unique_ptr<Peer>>& peers) {
  const auto ops = static_cast<std::int64_t>(env_number("EDGELAND_BENCH_CARVE_OPS", 10000));
  for (const auto& peer : peers) {
    benchmark::RegisterBenchmark(
        ("carving/" + peer->name()).c_str(),
        [p = peer.get()](benchmark::State& state) { run_carving(state, *p); })
        ->Arg(ops)
        ->Iterations(1)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace edgeland::bench
