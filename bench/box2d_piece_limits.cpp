// Where Box2D 2.4's b2PolygonShape::Set stops keeping convex_pieces()'s pieces exactly.
//
// Set recomputes each piece's hull by gift wrapping in float. A corner of a lattice polygon turns
// by at least twice-area 1 (orient >= 1 unit^2), which float sees as long as its rounding error
// on the cross products, about extent * (reach + extent) * 2^-23 units^2 for a piece of extent
// D (larger side of its box) at reach M (largest coordinate relative to the engine's origin),
// stays below that. This program measures it:
//   1. worst cases: pieces with one corner of orient exactly 1 (a sliver triangle of area 1/2
//      and a fat quadrilateral with that corner), of extent D at reach M, random directions;
//   2. the landscape of `edgeland demo` (tests/support/demo_landscape.hpp), every polygon cut
//      into convex pieces, at the world's corner as origin and at each polygon's cell corner.
// Each Set runs in a child process (tests/support/box2d_piece.hpp): Debian's Box2D is built with
// assertions, and a hull that float gets wrong can fail b2Assert and abort.
//
// Usage: box2d_piece_limits [trials per cell (200)] [demo edits (6000)]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "box2d_piece.hpp"
#include "edgeland/demo/landscape.hpp"
#include "edgeland/kernel/convex_pieces.hpp"
#include "edgeland/kernel/splitmix64.hpp"
#include "landscape_polygons.hpp"

namespace edgeland::bench {
namespace {

using testing::Box2dFrame;
using testing::Box2dVerdict;

void worst_case_table(int trials) {
  const std::vector<std::int64_t> extents{16, 64, 128, 256, 512, 1024, 2048, 4096};
  const std::vector<std::int64_t> reaches{256, 1024, 2048, 4096, 8192, 16384, 32768, 65536};
  std::printf(
      "Worst cases: failures (altered + aborted) among %d pieces per cell (sliver "
      "triangles, kinked quadrilaterals, 7-edge arcs); D = extent, M = reach, in units; "
      "0.01 m per unit\n\n",
      3 * trials);
  double largest_clean = 0, smallest_failing = 1e300;
  std::printf("| D \\ M |");
  for (std::int64_t m : reaches) std::printf(" %lld |", static_cast<long long>(m));
  std::printf("\n|---|");
  for (std::size_t i = 0; i < reaches.size(); ++i) std::printf("---|");
  std::printf("\n");
  SplitMix64 random(2024);
  for (std::int64_t d : extents) {
    std::printf("| %lld |", static_cast<long long>(d));
    for (std::int64_t m : reaches) {
      if (m < d) {
        std::printf(" - |");
        continue;
      }
      std::vector<Polygon> pieces;
      while (pieces.size() < static_cast<std::size_t>(3 * trials)) {
        const auto kind = static_cast<testing::LeastTurnKind>(pieces.size() % 3);
        const std::int64_t h = kind == testing::LeastTurnKind::kArc ? d / 7 : d / 2;
        const auto offset = static_cast<std::int64_t>(random.next() % (2 * h + 1)) - h;
        const Polygon p = testing::least_turn_piece(kind, d, offset, random.next() % 2 != 0);
        if (!p.empty())
          pieces.push_back(testing::placed(p, m, static_cast<int>(random.next() % 4)));
      }
      const std::vector<Box2dFrame> frames(pieces.size(), Box2dFrame{{0, 0}, 0.01});
      const std::vector<Box2dVerdict> v = testing::box2d_verdicts(pieces, frames);
      const auto aborted = std::count(v.begin(), v.end(), Box2dVerdict::kAborted);
      const auto altered = std::count(v.begin(), v.end(), Box2dVerdict::kAltered);
      const double product = static_cast<double>(d) * static_cast<double>(m + d);
      if (altered + aborted == 0) largest_clean = std::max(largest_clean, product);
      if (altered + aborted != 0) smallest_failing = std::min(smallest_failing, product);
      if (altered + aborted == 0)
        std::printf(" 0 |");
      else
        std::printf(" %ld (%ld aborts) |", static_cast<long>(altered + aborted),
                    static_cast<long>(aborted));
    }
    std::printf("\n");
  }
  std::printf("\nLargest D (M + D) without a failure: %.3g; smallest with one: %.3g\n",
              largest_clean, smallest_failing);
}

struct Tally {
  std::size_t pieces = 0, kept = 0, altered = 0, aborted = 0;
  double worst_product = 0;  // largest D (M + D) among the pieces
};

Tally landscape_tally(const std::vector<Polygon>& pieces, const std::vector<Box2dFrame>& frames) {
  Tally t;
  const std::vector<Box2dVerdict> v = testing::box2d_verdicts(pieces, frames);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    ++t.pieces;
    if (v[i] == Box2dVerdict::kKept) ++t.kept;
    if (v[i] == Box2dVerdict::kAltered) ++t.altered;
    if (v[i] == Box2dVerdict::kAborted) ++t.aborted;
    const double d = static_cast<double>(testing::extent(pieces[i]));
    const double m = static_cast<double>(testing::reach(pieces[i], frames[i].origin));
    t.worst_product = std::max(t.worst_product, d * (m + d));
  }
  return t;
}

void landscape_table(std::size_t edits) {
  const Landscape world = demo::demo_landscape(demo::kDemoWorld, 1, edits);
  std::vector<Polygon> pieces;
  std::vector<Point64> cells;
  std::size_t polygons = 0;
  for (const testing::CellPolygon& c : testing::landscape_polygons(world)) {
    ++polygons;
    for (Polygon& p : convex_pieces(c.polygon)) {
      pieces.push_back(std::move(p));
      cells.push_back(c.cell_corner);
    }
  }
  std::printf("\nThe demo world after %zu edits: %zu polygons, %zu convex pieces (N = 8)\n\n",
              edits, polygons, pieces.size());
  std::printf("| origin | m per unit | kept | altered | aborted | largest D (M + D) |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const double scale : {0.01, 0.005}) {
    for (const bool at_cell : {false, true}) {
      std::vector<Box2dFrame> frames;
      for (std::size_t i = 0; i < pieces.size(); ++i)
        frames.push_back({at_cell ? cells[i] : Point64{0, 0}, scale});
      const Tally t = landscape_tally(pieces, frames);
      std::printf("| %s | %.3f | %zu | %zu | %zu | %.3g |\n",
                  at_cell ? "cell corner" : "world corner", scale, t.kept, t.altered, t.aborted,
                  t.worst_product);
    }
  }
}

}  // namespace
}  // namespace edgeland::bench

int main(int argc, char** argv) {
  const int trials = argc > 1 ? std::atoi(argv[1]) : 200;
  const std::size_t edits = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 6000;
  edgeland::bench::worst_case_table(trials);
  edgeland::bench::landscape_table(edits);
}
