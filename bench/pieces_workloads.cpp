// Inputs of the triangulation and convex-decomposition benchmarks (pieces_workloads.hpp).
#include "pieces_workloads.hpp"

#include <stdexcept>

#include "edgeland/demo/landscape.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/validate.hpp"
#include "landscape_polygons.hpp"
#include "piece_shapes.hpp"
#include "validate_generators.hpp"

namespace edgeland::bench {
namespace {

PiecesWorkload checked(PiecesWorkload w) {
  for (const Polygon& p : w.polygons)
    if (!validate(p, 1).ok()) throw std::logic_error("invalid polygon in workload " + w.name);
  return w;
}

std::vector<PiecesWorkload> demo_workloads(std::size_t edits) {
  PiecesWorkload all{"demo", {}}, small{"demo_small", {}, true};
  for (const testing::CellPolygon& c :
       testing::landscape_polygons(demo::demo_landscape(demo::kDemoWorld, 1, edits))) {
    if (corners_only(c.polygon).size() <= 24) small.polygons.push_back(c.polygon);
    all.polygons.push_back(c.polygon);
  }
  return {checked(std::move(all)), checked(std::move(small))};
}

std::vector<PiecesWorkload> synthetic_workloads() {
  testing::SplitMixDraw draw(26);
  std::vector<PiecesWorkload> out;
  for (const std::int64_t n : {10'000, 100'000}) {
    const std::string size = std::to_string(n);
    out.push_back({"comb_" + size, {testing::unit_comb(n / 4, 5)}});
    out.push_back({"star_" + size, {testing::random_star(draw, {0, 0}, 100 * n, n)}});
    out.push_back({"box_" + size, {testing::box_with_side_vertices(draw, 10 * n, 10 * n, n / 4)}});
  }
  out.push_back({"spiral_10000", {*testing::polyomino_boundary(testing::spiral_cells(96))}});
  out.push_back({"spiral_100000", {*testing::polyomino_boundary(testing::spiral_cells(310))}});
  PiecesWorkload stars{"stars_40", {}, true};
  for (int i = 0; i < 200; ++i)
    stars.polygons.push_back(testing::random_star(draw, {0, 0}, 1000, 40));
  out.push_back(std::move(stars));
  for (PiecesWorkload& w : out) w = checked(std::move(w));
  return out;
}

}  // namespace

Polygon corners_only(const Polygon& p) {
  Polygon out;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (orientation(p[(i + p.size() - 1) % p.size()], p[i], p[(i + 1) % p.size()]) !=
        Orientation::kCollinear)
      out.push_back(p[i]);
  return out;
}

std::vector<PiecesWorkload> pieces_workloads(std::size_t demo_edits) {
  std::vector<PiecesWorkload> out = demo_workloads(demo_edits);
  for (PiecesWorkload& w : synthetic_workloads()) out.push_back(std::move(w));
  return out;
}

}  // namespace edgeland::bench
