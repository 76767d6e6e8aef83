#pragma once
// What the landscape benchmark families share: the rivals (the landscape in three tree
// configurations and the bitmap), one world type over them, per-edit timing, summaries, and
// the guard that turns an exception or a failed Landscape::check() into a benchmark error the
// smoke test sees.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "bitmap_world.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::bench {

// A number from the environment (sizes of the runs, so the smoke test can shrink them).
double env_number(const char* name, double fallback);
std::size_t env_count(const char* name, std::size_t fallback);

enum class Rival : std::uint8_t { kQuadtree, kKdTree, kGrid, kBitmap };
const char* rival_name(Rival rival);
std::optional<Rival> rival_named(const std::string& name);

// The landscape configuration of a rival: the default quadtree, the kd-tree, or a uniform grid
// of cells about kGridCell units wide (thesis 4.4).
inline constexpr std::int64_t kGridCell = 128;
LandscapeConfig landscape_config(Rival rival, std::int64_t world_side);

using World = std::variant<Landscape, BitmapWorld>;
World make_world(Rival rival, const Box64& box, Material fill);

enum class EditKind : std::uint8_t { kCarve, kFill, kReplace };
// Carve the shape, fill it with `material`, or replace `from` by `material` in it.
void apply(World& world, EditKind kind, const ValidSet& shape, Material material,
           Material from = kEmpty);
// One edit of a workload.
struct Edit {
  ValidSet shape;
  EditKind kind = EditKind::kCarve;
  Material material = kEmpty;
  Material from = kEmpty;  // kReplace's
};
inline void apply_edit(World& world, const Edit& e) {
  apply(world, e.kind, e.shape, e.material, e.from);
}
// The shapes as edits of one kind.
std::vector<Edit> edits_of(EditKind kind, const std::vector<ValidSet>& shapes, Material material);
Material material_at(const World& world, Point64 p);
bool is_landscape(const World& world);

// Wall-clock seconds of f() (steady_clock: the per-edit times are microseconds, where the
// thread CPU clock's system call would cost a visible share).
template <class F>
double seconds_of(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Applies every edit in turn, timing each one.
std::vector<double> time_edits(World& world, const std::vector<Edit>& edits);
// Applies the edits in frame batches of `size` (the last may be shorter), timing each batch: a
// landscape applies a batch as one edit (Landscape::apply_batch, rounded once), the bitmap paints
// its edits in turn. A size of 1 is time_edits.
std::vector<double> time_batches(World& world, const std::vector<Edit>& edits, std::size_t size);

// EDGELAND_LANDSCAPE_REPEATS (default 5): how often a timed run is repeated from the same start,
// keeping each edit's (or batch's) fastest time. The edits are deterministic, so every repeat
// does the same work; on a shared machine a preemption rarely hits the same edit twice.
std::size_t repeats();

// time_batches from `start`, repeats() times; each edit's (batch's) fastest time. `end`
// receives the world after the edits.
std::vector<double> fastest_edits(const World& start, const std::vector<Edit>& edits,
                                  std::optional<World>& end, std::size_t batch = 1);

// Query timing: per-query seconds of each batch of kQueryBatch queries (one steady_clock read
// costs ~30 ns, more than a bitmap lookup), each batch the fastest of repeats() passes.
// ask(i) answers query i.
inline constexpr std::size_t kQueryBatch = 64;
template <class Ask>
std::vector<double> batch_seconds(std::size_t n, Ask&& ask) {
  std::vector<double> out;
  for (std::size_t pass = 0; pass < repeats(); ++pass) {
    for (std::size_t from = 0, b = 0; from < n; from += kQueryBatch, ++b) {
      const std::size_t to = std::min(from + kQueryBatch, n);
      const double s = seconds_of([&] {
                         for (std::size_t i = from; i < to; ++i) ask(i);
                       }) /
                       static_cast<double>(to - from);
      if (pass == 0)
        out.push_back(s);
      else
        out[b] = std::min(out[b], s);
    }
  }
  return out;
}

// Nearest-rank quantile (q in [0, 1]) of the values; 0 for none.
double quantile(std::vector<double> values, double q);

struct EditSummary {
  double median_us = 0, p99_us = 0, mean_us = 0;
  std::vector<double> block_median_us;  // median of each block of edits (flatness)
};
EditSummary summarize(const std::vector<double>& seconds, std::size_t block);

// Sets the counters PREFIXmedian_us, PREFIXp99_us, PREFIXmean_us and blockNN_median_us.
void report(benchmark::State& state, const EditSummary& s, const std::string& prefix = "");

// Landscape size counters: polygons, vertices, cells, depth, bytes, bytes_per_vertex.
void report_stats(benchmark::State& state, const World& world);

// Runs body(); an exception becomes "landscape threw: ..." and, for a landscape world, a
// failing check() at the end "landscape check failed: ...": both reported as the benchmark's
// error and on stderr (the smoke test fails on either). Returns whether everything held.
template <class Body>
bool guarded(benchmark::State& state, Body&& body);
bool verify(benchmark::State& state, const World& world);
void fail(benchmark::State& state, const std::string& message);

template <class Body>
bool guarded(benchmark::State& state, Body&& body) {
  try {
    body();
    return true;
  } catch (const std::exception& e) {
    fail(state, std::string("landscape threw: ") + e.what());
    return false;
  }
}

// The world each rival ends landscape_edit/carve with (8192 x 8192, EDITS 32-gons carved):
// the start of the fill workload and of the snapshot benchmark. Made once per process.
World carve_workload_end(Rival rival);

// Registration of each family (names FAMILY/.../RIVAL[/SIZE]).
void register_edit_benchmarks();
void register_query_benchmarks();
void register_scaling_benchmarks();
void register_crossover_benchmarks();
void register_snapshot_benchmarks();
void register_save_load_benchmarks();
void register_big_shape_benchmarks();

}  // namespace edgeland::bench
