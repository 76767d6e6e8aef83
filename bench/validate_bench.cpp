// validate_bench: the kernel's validate() on valid inputs of the kinds the clipper checks
// before every operation. Wall time here is noisy on a shared machine; for comparisons count
// instructions instead, e.g.
//   valgrind --tool=callgrind ./validate_bench --benchmark_filter=circle
//     --benchmark_min_time=0.001
// Families (each input is built once, checked valid, then validated in the timed loop):
//   stars     two smooth 10^4-vertex star rings side by side (a set of 2)
//   circle    one 10^5-vertex circle of radius 10^8
//   carved    an 8192 x 8192 square minus 300 32-gons of radius 40, one clip difference at
//             a time (the carving workload)
//   grid      100 x 100 squares of side 10 sharing edges (a set of 10^4)
//   spiky     a 10^5-vertex star with radii from 1 to 10^8 (about 15,000 edges cut by a
//             vertical line: the wide-status case)
// Built with -DEDGELAND_BUILD_BENCH=ON; the inputs are made with floating point here, outside
// the library, and rounded to integers.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/splitmix64.hpp"
#include "edgeland/kernel/validate.hpp"

namespace {

using edgeland::ClipOp;
using edgeland::Point64;
using edgeland::Polygon;
using edgeland::PolygonSet;

using edgeland::SplitMix64;  // deterministic on every platform

// n vertices at angles 2 pi i / n and radius radius(angle) around `center`, repeated
// points dropped.
Polygon star(Point64 center, std::size_t n, const std::function<double(double)>& radius) {
  Polygon ring;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    const double r = radius(t);
    const Point64 v{center.x + std::llround(r * std::cos(t)),
                    center.y + std::llround(r * std::sin(t))};
    if (ring.empty() || (ring.back() != v && ring.front() != v)) ring.push_back(v);
  }
  return ring;
}

PolygonSet smooth_stars() {
  return {
      star({0, 0}, 10'000, [](double t) { return 1e6 * (1 + 0.25 * std::sin(7 * t)); }),
      star({3'000'000, 0}, 10'000, [](double t) { return 1e6 * (1 + 0.25 * std::sin(5 * t)); })};
}

PolygonSet circle() {
  return {star({0, 0}, 100'000, [](double) { return 1e8; })};
}

PolygonSet carved() {
  PolygonSet set{{{0, 0}, {8192, 0}, {8192, 8192}, {0, 8192}}};
  SplitMix64 random(0xCA4F1A6);
  for (int i = 0; i < 300; ++i) {
    const Point64 center{static_cast<std::int64_t>(random.next() % 8193),
                         static_cast<std::int64_t>(random.next() % 8193)};
    const PolygonSet hole{star(center, 32, [](double) { return 40.0; })};
    set = edgeland::clip(ClipOp::kDifference, set, hole).polygons;
  }
  return set;
}

PolygonSet grid() {
  PolygonSet set;
  for (std::int64_t i = 0; i < 100; ++i) {
    for (std::int64_t j = 0; j < 100; ++j) {
      const std::int64_t x = 10 * i, y = 10 * j;
      set.push_back({{x, y}, {x + 10, y}, {x + 10, y + 10}, {x, y + 10}});
    }
  }
  return set;
}

// Random directions of length up to 10^8 in angular order (parallel ones merged), as
// vertices around the origin: a star-shaped ring whose radius jumps from vertex to vertex.
PolygonSet spiky_star() {
  SplitMix64 random(20261122);
  const auto coordinate = [&] {
    return static_cast<std::int64_t>(random.next() % 200'000'001) - 100'000'000;
  };
  std::vector<Point64> d;
  while (d.size() < 100'000) {
    const Point64 p{coordinate(), coordinate()};
    if (p != Point64{}) d.push_back(p);
  }
  // Exact angle order: upper half-plane (and the positive x axis) first, then by turn.
  const auto half = [](Point64 p) { return p.y > 0 || (p.y == 0 && p.x > 0) ? 0 : 1; };
  const auto cross = [](Point64 a, Point64 b) { return a.x * b.y - a.y * b.x; };
  std::sort(d.begin(), d.end(), [&](Point64 a, Point64 b) {
    return half(a) != half(b) ? half(a) < half(b) : cross(a, b) > 0;
  });
  Polygon ring;
  for (const Point64 p : d) {
    if (!ring.empty() && half(ring.back()) == half(p) && cross(ring.back(), p) == 0) continue;
    ring.push_back(p);
  }
  return {ring};
}

void run(benchmark::State& state, const PolygonSet& set) {
  std::size_t vertices = 0;
  for (const Polygon& p : set) vertices += p.size();
  for (auto _ : state) {
    const edgeland::ValidationReport report = edgeland::validate(set);
    benchmark::DoNotOptimize(report.violations.data());
  }
  state.counters["polygons"] = static_cast<double>(set.size());
  state.counters["vertices"] = static_cast<double>(vertices);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * vertices));
}

// Builds each input once and registers it; an invalid input is a bug in this file.
void register_family(const char* name, PolygonSet (*make)()) {
  static std::deque<PolygonSet> inputs;  // registered benchmarks keep references
  inputs.push_back(make());
  const PolygonSet& set = inputs.back();
  const edgeland::ValidationReport report = edgeland::validate(set);
  if (!report.ok()) {
    std::fprintf(stderr, "validate_bench: %s input invalid: %s\n", name,
                 report.violations.front().describe().c_str());
    std::exit(1);
  }
  benchmark::RegisterBenchmark((std::string("validate/") + name).c_str(),
                               [&set](benchmark::State& state) { run(state, set); })
      ->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
  register_family("stars", smooth_stars);
  register_family("circle", circle);
  register_family("carved", carved);
  register_family("grid", grid);
  register_family("spiky", spiky_star);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
