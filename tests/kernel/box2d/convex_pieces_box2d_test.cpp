// convex_pieces() into Box2D 2.4 (Debian's libbox2d 2.4.1): b2PolygonShape::Set must keep every
// piece exactly (m_count equal to the piece's size, the same vertices in the same cyclic order),
// as the game layer hands them over: coordinates relative to a nearby origin, one unit at least
// b2_linearSlop (0.005 m). Set recomputes the hull in float; bench/box2d_piece_limits measures
// where that stops working (bench/README.md): no loss seen while extent * (reach + extent) stays
// below 2^23 units^2, so 2^22 is the bound promised in convex_pieces.hpp and checked here with
// the worst pieces a lattice has. Each Set runs in a child process (tests/support/box2d_piece):
// Debian builds Box2D with assertions, and a hull float gets wrong can abort.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "edgeland/demo/landscape.hpp"
#include "edgeland/kernel/convex_pieces.hpp"
#include "support/box2d_piece.hpp"
#include "support/landscape_polygons.hpp"
#include "support/validate_generators.hpp"

namespace edgeland::testing {
namespace {

std::size_t count_not_kept(const std::vector<Polygon>& pieces,
                           const std::vector<Box2dFrame>& frames) {
  const std::vector<Box2dVerdict> v = box2d_verdicts(pieces, frames);
  return static_cast<std::size_t>(
      std::count_if(v.begin(), v.end(), [](Box2dVerdict x) { return x != Box2dVerdict::kKept; }));
}

TEST(ConvexPiecesBox2d, DemoWorldPiecesAreKept) {
  // The world of `edgeland demo` after 2,000 of its players' edits: layers under wavy lines,
  // rough explosions, capsule tunnels, pools; every polygon cut at its cell's lines.
  const Landscape world = demo::demo_landscape(demo::kDemoWorld, 1, 2000);
  std::vector<Polygon> pieces;
  std::vector<Point64> cells;
  std::int64_t largest = 0;
  for (const CellPolygon& c : landscape_polygons(world)) {
    for (Polygon& p : convex_pieces(c.polygon)) {
      largest = std::max(largest, extent(p) * (reach(p, {0, 0}) + extent(p)));
      pieces.push_back(std::move(p));
      cells.push_back(c.cell_corner);
    }
  }
  std::printf("%zu pieces, largest extent * (reach + extent) from the world corner: %lld\n",
              pieces.size(), static_cast<long long>(largest));
  ASSERT_GT(pieces.size(), 10'000u);
  for (const double meters : {0.01, 0.005}) {
    std::vector<Box2dFrame> at_world, at_cell;
    for (const Point64& c : cells) {
      at_world.push_back({demo::kDemoWorld.min, meters});
      at_cell.push_back({c, meters});
    }
    EXPECT_EQ(count_not_kept(pieces, at_world), 0u) << meters << " m per unit, world corner";
    EXPECT_EQ(count_not_kept(pieces, at_cell), 0u) << meters << " m per unit, cell corner";
  }
}

TEST(ConvexPiecesBox2d, LeastTurnPiecesWithinTheBoundAreKept) {
  // extent D and reach M with D (M + D) <= 2^22: slivers of area 1/2, kinked quadrilaterals and
  // 7-edge arcs, every corner turning by the lattice's least angle, in random directions.
  constexpr std::int64_t kBound = std::int64_t{1} << 22;
  SplitMixDraw draw(26);
  for (const std::int64_t d : {16, 64, 256, 1024, 1448}) {
    std::vector<Polygon> pieces;
    while (pieces.size() < 300) {
      const auto kind = static_cast<LeastTurnKind>(pieces.size() % 3);
      const std::int64_t h = kind == LeastTurnKind::kArc ? d / 7 : d / 2;
      const Polygon p = least_turn_piece(kind, d, draw(-h, h + 1), draw(0, 2) == 1);
      if (p.empty()) continue;
      // As far out as the bound allows for this piece's extent e: reach e (M + e) <= 2^22.
      const std::int64_t e = extent(p), m = std::max(e, kBound / e - e);
      const Polygon q = placed(p, m, static_cast<int>(draw(0, 4)));
      if (e * (reach(q, {0, 0}) + e) > kBound) continue;  // e > 2^11: no room
      pieces.push_back(q);
    }
    const std::vector<Box2dFrame> frames(pieces.size(), Box2dFrame{{0, 0}, 0.01});
    EXPECT_EQ(count_not_kept(pieces, frames), 0u) << "extent about " << d;
  }
}

TEST(ConvexPiecesBox2d, TheCheckSeesADroppedVertex) {
  // Set drops a straight vertex from its hull: the check must notice (a piece of convex_pieces()
  // never has one).
  const std::vector<Polygon> square{{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}};
  EXPECT_EQ(count_not_kept(square, {Box2dFrame{{0, 0}, 0.01}}), 1u);
}

TEST(ConvexPiecesBox2d, FarBeyondTheBoundBox2dLosesVertices) {
  // Why the bound: extent 4096 at reach 65536 (D (M + D) about 2^28), and float loses corners
  // of most least-turn pieces (bench/README.md has the whole table).
  SplitMixDraw draw(27);
  std::vector<Polygon> pieces;
  while (pieces.size() < 30) {
    const Polygon p = least_turn_piece(LeastTurnKind::kKinkedQuad, 4096, draw(-2048, 2049), false);
    if (!p.empty()) pieces.push_back(placed(p, 65536, 0));
  }
  const std::vector<Box2dFrame> frames(pieces.size(), Box2dFrame{{0, 0}, 0.01});
  EXPECT_GT(count_not_kept(pieces, frames), 5u);
}

}  // namespace
}  // namespace edgeland::testing
