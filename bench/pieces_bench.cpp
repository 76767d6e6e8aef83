// edgeland_pieces_bench: triangulate() against CGAL's constrained Delaunay triangulation, and
// convex_pieces() against CGAL's convex partitions, on the demo world's polygons and synthetic
// ones (pieces_workloads.hpp); bench/README.md "Triangulation and convex pieces" and
// run_pieces.sh. Every benchmark checks its result's count (n - 2 triangles; pieces reported,
// not judged) and reports it as a counter:
//   triangulate/{edgeland,cgal_cdt}/WORKLOAD            items = triangles (triangles/s)
//   triangulate/validate_only/WORKLOAD                  validate() alone, the input check
//   convex_pieces/{edgeland_8,edgeland_unbounded,cgal_approx,cgal_greene,cgal_optimal}/WORKLOAD
// cgal_optimal only on the small workloads (O(n^4)). EDGELAND_PIECES_DEMO_EDITS sets the demo
// world's edits (default 6000, the demo's own).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <functional>
#include <limits>
#include <string>

#include "cgal_pieces.hpp"
#include "edgeland/kernel/convex_pieces.hpp"
#include "edgeland/kernel/triangulate.hpp"
#include "edgeland/kernel/validate.hpp"
#include "pieces_workloads.hpp"

namespace edgeland::bench {
namespace {

std::size_t triangle_count(const PiecesWorkload& w) {
  std::size_t n = 0;
  for (const Polygon& p : w.polygons) n += p.size() - 2;
  return n;
}

void report(benchmark::State& state, const PiecesWorkload& w, std::size_t produced,
            const char* what) {
  state.counters["polygons"] = static_cast<double>(w.polygons.size());
  state.counters["triangles"] = static_cast<double>(triangle_count(w));
  state.counters[what] = static_cast<double>(produced);
}

void triangulate_edgeland(benchmark::State& state, const PiecesWorkload& w) {
  std::size_t produced = 0;
  for (auto _ : state) {
    produced = 0;
    for (const Polygon& p : w.polygons) produced += triangulate(p).size();
    benchmark::ClobberMemory();
  }
  if (produced != triangle_count(w)) state.SkipWithError("edgeland: not n - 2 triangles");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * produced));
  report(state, w, produced, "faces");
}

// The input check both algorithms start with, alone: how much of their time it is.
void validate_only(benchmark::State& state, const PiecesWorkload& w) {
  std::size_t valid = 0;
  for (auto _ : state) {
    valid = 0;
    for (const Polygon& p : w.polygons) valid += validate(p, 1).ok();
  }
  if (valid != w.polygons.size()) state.SkipWithError("validate: an invalid polygon");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * triangle_count(w)));
  report(state, w, triangle_count(w), "faces");
}

void triangulate_cgal(benchmark::State& state, const PiecesWorkload& w) {
  std::size_t produced = 0;
  for (auto _ : state) {
    produced = 0;
    for (const Polygon& p : w.polygons) produced += cgal_cdt_inside_faces(p);
  }
  if (produced != triangle_count(w)) state.SkipWithError("cgal_cdt: not n - 2 inside faces");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * produced));
  report(state, w, produced, "faces");
}

void pieces_edgeland(benchmark::State& state, const PiecesWorkload& w, std::size_t n) {
  std::size_t produced = 0;
  for (auto _ : state) {
    produced = 0;
    for (const Polygon& p : w.polygons) produced += convex_pieces(p, n).size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * produced));
  report(state, w, produced, "pieces");
}

void pieces_cgal(benchmark::State& state, const PiecesWorkload& w, CgalPartition kind) {
  std::vector<Polygon> corners;  // CGAL's partitions are given polygons without straight vertices
  for (const Polygon& p : w.polygons) corners.push_back(corners_only(p));
  std::size_t produced = 0;
  for (auto _ : state) {
    produced = 0;
    for (const Polygon& p : corners) produced += cgal_convex_partition(p, kind);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * produced));
  report(state, w, produced, "pieces");
}

void register_all(const std::vector<PiecesWorkload>& workloads) {
  constexpr std::size_t kUnbounded = std::numeric_limits<std::size_t>::max();
  for (const PiecesWorkload& w : workloads) {
    const auto add = [&](const std::string& name, auto f) {
      benchmark::RegisterBenchmark(name.c_str(), f)->Unit(benchmark::kMillisecond);
    };
    add("triangulate/edgeland/" + w.name,
        [&w](benchmark::State& s) { triangulate_edgeland(s, w); });
    add("triangulate/cgal_cdt/" + w.name, [&w](benchmark::State& s) { triangulate_cgal(s, w); });
    add("triangulate/validate_only/" + w.name, [&w](benchmark::State& s) { validate_only(s, w); });
    add("convex_pieces/edgeland_8/" + w.name,
        [&w](benchmark::State& s) { pieces_edgeland(s, w, kDefaultMaxPieceVertices); });
    add("convex_pieces/edgeland_unbounded/" + w.name,
        [&w](benchmark::State& s) { pieces_edgeland(s, w, kUnbounded); });
    add("convex_pieces/cgal_approx/" + w.name,
        [&w](benchmark::State& s) { pieces_cgal(s, w, CgalPartition::kApprox); });
    add("convex_pieces/cgal_greene/" + w.name,
        [&w](benchmark::State& s) { pieces_cgal(s, w, CgalPartition::kGreene); });
    if (w.optimal)
      add("convex_pieces/cgal_optimal/" + w.name,
          [&w](benchmark::State& s) { pieces_cgal(s, w, CgalPartition::kOptimal); });
  }
}

}  // namespace
}  // namespace edgeland::bench

int main(int argc, char** argv) {
  const char* edits = std::getenv("EDGELAND_PIECES_DEMO_EDITS");
  static const auto workloads =
      edgeland::bench::pieces_workloads(edits ? std::strtoull(edits, nullptr, 10) : 6000);
  edgeland::bench::register_all(workloads);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
