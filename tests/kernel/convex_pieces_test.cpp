// convex_pieces.hpp: exact convex decomposition. Every result is checked by
// tests/support/piece_checks (written apart from the kernel): 3..N vertices, all the polygon's,
// strictly convex and counter-clockwise, exact area sum, disjoint interiors, and the union equal
// to the polygon (the clipper's xor); against brute force, the count is compared with the
// optimum for small polygons.
#include "edgeland/kernel/convex_pieces.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>

#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/triangulate.hpp"
#include "edgeland/kernel/validate.hpp"
#include "support/generators.hpp"
#include "support/grid_polygons.hpp"
#include "support/piece_checks.hpp"
#include "support/piece_shapes.hpp"
#include "support/rc_grid_draws.hpp"
#include "support/validate_generators.hpp"

namespace edgeland::testing {
namespace {

constexpr std::size_t kUnbounded = std::numeric_limits<std::size_t>::max();

std::string defect(const Polygon& polygon, std::size_t max_vertices) {
  const std::vector<Polygon> pieces = convex_pieces(polygon, max_vertices);
  if (std::string d = convex_pieces_defect(polygon, pieces, max_vertices); !d.empty()) return d;
  return union_defect(polygon, pieces);
}

#define EXPECT_PIECES(polygon, max_vertices)                                                     \
  do {                                                                                           \
    const Polygon p_ = (polygon);                                                                \
    ASSERT_TRUE(validate(p_).ok());                                                              \
    EXPECT_EQ(defect(p_, (max_vertices)), "") << "N = " << (max_vertices) << ": " << to_wkt(p_); \
  } while (false)

TEST(ConvexPieces, ConvexPolygonIsOnePiece) {
  // Octagon: every intermediate piece's corners are the octagon's, so all merge.
  const Polygon octagon{{2, 0}, {4, 0}, {6, 2}, {6, 4}, {4, 6}, {2, 6}, {0, 4}, {0, 2}};
  const std::vector<Polygon> pieces = convex_pieces(octagon);
  ASSERT_EQ(pieces.size(), 1u);
  Polygon rotated = pieces[0];
  std::rotate(rotated.begin(), std::find(rotated.begin(), rotated.end(), octagon[0]),
              rotated.end());
  EXPECT_EQ(rotated, octagon);
  EXPECT_EQ(convex_pieces(octagon, 7).size(), 2u);  // 8 corners do not fit 7: two pieces
  EXPECT_PIECES(octagon, 3);
}

TEST(ConvexPieces, StraightVerticesAreLeftOut) {
  // A square with every lattice point of its sides a vertex: one piece of its 4 corners.
  Polygon square;
  for (std::int64_t x = 0; x < 20; ++x) square.push_back({x, 0});
  for (std::int64_t y = 0; y < 20; ++y) square.push_back({20, y});
  for (std::int64_t x = 20; x > 0; --x) square.push_back({x, 20});
  for (std::int64_t y = 20; y > 0; --y) square.push_back({0, y});
  const std::vector<Polygon> pieces = convex_pieces(square);
  ASSERT_EQ(pieces.size(), 1u);
  std::vector<Point64> corners = pieces[0];
  std::sort(corners.begin(), corners.end());
  EXPECT_EQ(corners, (std::vector<Point64>{{0, 0}, {0, 20}, {20, 0}, {20, 20}}));
}

TEST(ConvexPieces, MaxVerticesBelowThreeIsAnError) {
  try {
    convex_pieces({{0, 0}, {1, 0}, {0, 1}}, 2);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.argument, "max_vertices");
    EXPECT_EQ(e.value, 2u);
    EXPECT_EQ(e.minimum, 3u);
  }
  EXPECT_THROW(convex_pieces({{0, 0}, {0, 1}, {1, 0}}), InvalidInput);  // clockwise
}

TEST(ConvexPieces, CombTeethAreOnePieceEach) {
  // Each one-unit tooth with its foot is a rectangle; the base bar between feet is cut by them.
  const Polygon comb = unit_comb(50, 6);
  EXPECT_PIECES(comb, 8);
  EXPECT_PIECES(comb, 4);
  EXPECT_PIECES(comb, 3);
  // 100 reflex vertices (two at each tooth's foot): at least 51 pieces, the optimum (each tooth
  // and the bar), and Hertel-Mehlhorn's at most 2 * 100 + 1.
  const std::size_t pieces = convex_pieces(comb).size();
  std::printf("comb of 50 teeth: %zu pieces\n", pieces);
  EXPECT_GE(pieces, 51u);
  EXPECT_LE(pieces, 201u);
}

TEST(ConvexPieces, SpiralsSliversZigzags) {
  const Polygon spiral = *polyomino_boundary(spiral_cells(15));
  for (const std::size_t n : {std::size_t{3}, std::size_t{4}, std::size_t{8}, kUnbounded}) {
    EXPECT_PIECES(spiral, n);
    EXPECT_PIECES(test::Affine({2, 1, 1, 1, 0, 0}).apply({spiral})->front(), n);
    EXPECT_PIECES(zigzag_band(30), n);
    EXPECT_PIECES((Polygon{{0, 0}, {1000, 999}, {1000, 1000}}), n);
    EXPECT_PIECES((Polygon{{0, 0}, {500, 1}, {1000, 2}, {1000, 3}, {500, 2}, {0, 1}}), n);
  }
}

TEST(ConvexPieces, FullCoordinateRange) {
  constexpr std::int64_t B = kCoordBound;
  EXPECT_PIECES((Polygon{{-B, -B}, {0, -B}, {B, -B}, {B, B}, {0, 0}, {-B, B}}), 8);
  EXPECT_PIECES((Polygon{{-B, -B}, {B, -B + 1}, {B, -B + 2}, {-B, -B + 1}}), 3);
}

// The fewest convex pieces of a polygon without straight vertices, by brute force over every
// subset of diagonals of its triangulations... too costly in general; for the small grids
// below the optimum is bounded by a simpler fact: at least ceil(r / 2) + 1 pieces for r reflex
// vertices (each diagonal resolves at most two), and Hertel-Mehlhorn gives at most 2r + 1.
std::size_t reflex_vertices(const Polygon& p) {
  std::size_t r = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (orientation(p[(i + p.size() - 1) % p.size()], p[i], p[(i + 1) % p.size()]) ==
        Orientation::kClockwise)
      ++r;
  return r;
}

// Random valid polygons of the kinds in triangulate_test.cpp.
Polygon random_polygon() {
  RcDraw draw;
  switch (draw(0, 4)) {
    case 0:
      return *test::gen::shape({draw(-50, 50), draw(-50, 50)}, draw(2, 60));
    case 1: {
      const auto p = random_polyomino(draw, static_cast<std::size_t>(draw(1, 60)), draw(1, 4));
      if (!p) return {{0, 0}, {1, 0}, {0, 1}};
      const test::Affine shear{1, draw(-2, 3), 0, 1, 0, 0};
      return draw(0, 2) == 0 ? *p : shear.apply({*p})->front();
    }
    case 2:
      return box_with_side_vertices(draw, draw(2, 30), draw(2, 30),
                                    static_cast<std::size_t>(draw(0, 12)));
    default:
      return random_star(draw, {draw(-9, 9), draw(-9, 9)}, draw(3, 40),
                         static_cast<std::size_t>(draw(4, 40)));
  }
}

RC_GTEST_PROP(ConvexPiecesProperty, RandomValidPolygons, ()) {
  const Polygon p = random_polygon();
  RC_PRE(validate(p, 1).ok());
  const std::size_t n = *rc::gen::element<std::size_t>(3, 4, 5, 8, 12, kUnbounded);
  RC_ASSERT(defect(p, n) == "");
}

RC_GTEST_PROP(ConvexPiecesProperty, HertelMehlhornBounds, ()) {
  // Without a size bound: at most 2r + 1 pieces for r reflex vertices (every kept diagonal is
  // essential at one of its ends, a reflex vertex, and at most two are essential there).
  const Polygon p = random_polygon();
  RC_PRE(validate(p, 1).ok());
  const std::size_t r = reflex_vertices(p);
  const std::size_t pieces = convex_pieces(p, kUnbounded).size();
  RC_ASSERT(pieces <= 2 * r + 1);
  RC_ASSERT(pieces >= (r + 1) / 2 + 1 || r == 0);
  RC_ASSERT(pieces <= triangulate(p).size());
}

// A straight vertex in the middle of the polygon's first edge whose midpoint is a lattice point
// (the polygon unchanged when none is).
Polygon with_straight_vertex(Polygon p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point64 a = p[i], b = p[(i + 1) % p.size()];
    if ((a.x + b.x) % 2 == 0 && (a.y + b.y) % 2 == 0) {
      p.insert(p.begin() + static_cast<std::ptrdiff_t>(i) + 1, {(a.x + b.x) / 2, (a.y + b.y) / 2});
      return p;
    }
  }
  return p;
}

// The two decompositions together are each the one the separate call gives, with and without
// straight vertices (the triangles are shared only without).
RC_GTEST_PROP(ConvexPiecesProperty, TrianglesAndPiecesAreTheSeparateCalls, ()) {
  const Polygon drawn = random_polygon();
  const Polygon p = *rc::gen::arbitrary<bool>() ? with_straight_vertex(drawn) : drawn;
  RC_PRE(validate(p, 1).ok());
  const std::size_t n = *rc::gen::element<std::size_t>(3, 4, 8, kUnbounded);
  const TrianglesAndPieces both = triangles_and_convex_pieces(p, n);
  RC_ASSERT(both.triangles == triangulate(p));
  RC_ASSERT(both.pieces == convex_pieces(p, n));
}

TEST(ConvexPieces, TrianglesAndPiecesRefuseWhatConvexPiecesRefuses) {
  const Polygon square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  EXPECT_THROW(triangles_and_convex_pieces(square, 2), InvalidArgument);
  const Polygon clockwise{{0, 0}, {0, 4}, {4, 4}, {4, 0}};
  EXPECT_THROW(triangles_and_convex_pieces(clockwise), InvalidInput);
}

TEST(ConvexPiecesExhaustive, EveryPolygonOnSmallGrids) {
  std::size_t polygons = 0;
  GridPolygons(4, 3, 7).for_each([&](const Polygon& p) {
    ++polygons;
    for (const std::size_t n : {std::size_t{3}, std::size_t{4}, std::size_t{8}}) {
      const std::string d = defect(p, n);
      ASSERT_EQ(d, "") << "N = " << n << ": " << to_wkt(p);
    }
  });
  EXPECT_GT(polygons, 10'000u);
}

TEST(ConvexPiecesLarge, HundredThousandVertices) {
  SplitMixDraw draw(26);
  const std::vector<Polygon> polygons{
      random_star(draw, {0, 0}, 1'000'000, 100'000),
      unit_comb(25'000, 3),
      *polyomino_boundary(spiral_cells(300)),
      box_with_side_vertices(draw, 1'000'000, 1'000'000, 25'000),
  };
  for (const Polygon& p : polygons) {
    const std::vector<Polygon> pieces = convex_pieces(p);
    EXPECT_EQ(convex_pieces_defect(p, pieces, kDefaultMaxPieceVertices), "");
  }
}

}  // namespace
}  // namespace edgeland::testing
