// Big shapes (landscape_big_shapes.hpp): a comb set filled into an empty 4096 x 4096 world and
// carved back out, each as one edit, against the bitmap doing the same. The landscape's cost
// grows with the cells touched and the vertices of the shape that reach each cell; the carve
// back meets the cells the fill split.
//
// Names landscape_big/combs/VERTICES (1,000, 10,000 and 106,000); counters fill_ms,
// carve_back_ms, back_vs_fill, the bitmap's bitmap_fill_ms and bitmap_carve_back_ms, and the
// world after the fill (cells, vertices). Each edit is timed once (the 106k carve back took
// 75-88 s when each cell saw every comb reaching it).
#include "landscape_big_shapes.hpp"

#include <string>

#include "landscape_common.hpp"

namespace edgeland::bench {

ValidSet comb_set(std::size_t vertices) {
  const std::size_t combs = (vertices + 8163) / 8164;
  const std::size_t teeth = (vertices / combs - 4) / 4;
  const std::int64_t pitch = (kBigShapeWorld.max.y - kBigShapeWorld.min.y) / (combs + 1);
  const std::int64_t base = 8, height = 250, x0 = 4;
  const std::int64_t x1 = x0 + 2 * static_cast<std::int64_t>(teeth) + 1;
  PolygonSet set;
  for (std::size_t c = 0; c < combs; ++c) {
    const std::int64_t y0 = kBigShapeWorld.min.y + pitch / 2 + static_cast<std::int64_t>(c) * pitch;
    const std::int64_t top = y0 + base;
    Polygon comb{{x0, y0}, {x1, y0}, {x1, top}};
    // Along the top from right to left: each tooth up its right side and down its left.
    for (std::size_t i = teeth; i-- > 0;) {
      const std::int64_t tx = x0 + 1 + 2 * static_cast<std::int64_t>(i);
      comb.insert(comb.end(),
                  {{tx + 1, top}, {tx + 1, top + height}, {tx, top + height}, {tx, top}});
    }
    comb.push_back({x0, top});
    set.push_back(std::move(comb));
  }
  return ValidSet(std::move(set), Operand::kClip);
}

namespace {

struct BigRun {
  double fill_s = 0, carve_back_s = 0;
  std::optional<World> after_fill;
};

BigRun fill_and_carve_back(Rival rival, const ValidSet& shape) {
  BigRun r;
  World world = make_world(rival, kBigShapeWorld, kEmpty);
  r.fill_s = seconds_of([&] { apply(world, EditKind::kFill, shape, 1); });
  r.after_fill.emplace(world);
  r.carve_back_s = seconds_of([&] { apply(world, EditKind::kCarve, shape, kEmpty); });
  return r;
}

void run_big(benchmark::State& state, std::size_t vertices) {
  const ValidSet shape = comb_set(vertices);
  BigRun bitmap, landscape;
  for (auto _ : state) {
    bitmap = fill_and_carve_back(Rival::kBitmap, shape);
    if (!guarded(state, [&] { landscape = fill_and_carve_back(Rival::kQuadtree, shape); })) return;
    state.SetIterationTime(landscape.fill_s + landscape.carve_back_s);
  }
  if (!verify(state, *landscape.after_fill)) return;
  state.counters["fill_ms"] = landscape.fill_s * 1e3;
  state.counters["carve_back_ms"] = landscape.carve_back_s * 1e3;
  state.counters["back_vs_fill"] = landscape.carve_back_s / landscape.fill_s;
  state.counters["bitmap_fill_ms"] = bitmap.fill_s * 1e3;
  state.counters["bitmap_carve_back_ms"] = bitmap.carve_back_s * 1e3;
  state.counters["fill_vs_bitmap"] = landscape.fill_s / bitmap.fill_s;
  state.counters["carve_back_vs_bitmap"] = landscape.carve_back_s / bitmap.carve_back_s;
  report_stats(state, *landscape.after_fill);
}

}  // namespace

void register_big_shape_benchmarks() {
  for (std::size_t vertices : {1000, 10000, 106000}) {
    const std::string name = "landscape_big/combs/" + std::to_string(vertices);
    benchmark::RegisterBenchmark(name.c_str(),
                                 [vertices](benchmark::State& state) { run_big(state, vertices); })
        ->Iterations(1)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace edgeland::bench
