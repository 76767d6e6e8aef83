// perimeter.hpp: exact integer square root and perimeter bounds (thesis 2.2).
#include "edgeland/kernel/perimeter.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "exact_reference.hpp"
#include "random_geometry.hpp"
#include "support/big_int.hpp"

namespace edgeland::test {
namespace {

using U = UInt128;

TEST(Isqrt, SmallValuesAndPerfectSquares) {
  EXPECT_EQ(isqrt(0), U(0));
  EXPECT_EQ(isqrt(1), U(1));
  EXPECT_EQ(isqrt(3), U(1));
  EXPECT_EQ(isqrt(4), U(2));
  EXPECT_EQ(isqrt(99), U(9));
  EXPECT_EQ(isqrt(100), U(10));
}

TEST(Isqrt, TopOfTheUnsignedRange) {
  const U max64 = ~std::uint64_t(0);       // 2^64 - 1
  EXPECT_EQ(isqrt(~U(0)), max64);          // 2^128 - 1
  EXPECT_EQ(isqrt(max64 * max64), max64);  // largest perfect square
  EXPECT_EQ(isqrt(max64 * max64 - 1), max64 - 1);
  EXPECT_EQ(isqrt(U(1) << 127), U(0xB504F333F9DE6484ull));  // floor(2^63.5)
}

TEST(PerimeterBounds, AxisAlignedFullRangeSquareIsExact) {
  const Ring square{{-B, -B}, {B, -B}, {B, B}, {-B, B}};
  const Int128 expected = 4 * (2 * Int128(B));
  EXPECT_EQ(perimeter_bounds(square), (PerimeterBounds{expected, expected}));
}

TEST(PerimeterBounds, PythagoreanTriangleIsExact) {
  EXPECT_EQ(perimeter_bounds(Ring{{0, 0}, {3, 0}, {0, 4}}), (PerimeterBounds{12, 12}));
}

TEST(PerimeterBounds, UnitDiamondBracketsFourRootTwo) {
  // Four edges of length sqrt(2) = 1.414...: each contributes 1 to lo and 2 to hi.
  EXPECT_EQ(perimeter_bounds(Ring{{1, 0}, {2, 1}, {1, 2}, {0, 1}}), (PerimeterBounds{4, 8}));
}

TEST(PerimeterBounds, LongestDiagonalAtTheBound) {
  // Edge (-B,-B) -> (B,B) and back: length 2B * sqrt(2) each way.
  const PerimeterBounds b = perimeter_bounds(Ring{{-B, -B}, {B, B}});
  const cpp_int squared = 2 * cpp_int(2 * B) * (2 * B);
  const cpp_int root = sqrt(squared);
  EXPECT_EQ(big(b.lo), 2 * root);
  EXPECT_EQ(big(b.hi), 2 * (root + 1));
}

TEST(PerimeterBounds, SetSumsItsMembers) {
  const PolygonSet set{{{0, 0}, {3, 0}, {0, 4}}, {{1, 0}, {2, 1}, {1, 2}, {0, 1}}};
  EXPECT_EQ(perimeter_bounds(set), (PerimeterBounds{16, 20}));
}

RC_GTEST_PROP(IsqrtProperty, MatchesCppIntSqrt, ()) {
  const auto hi = *rc::gen::arbitrary<std::uint64_t>();
  const auto lo = *rc::gen::arbitrary<std::uint64_t>();
  const int shift = *rc::gen::inRange(0, 128);
  U n = ((U(hi) << 64) | lo) >> shift;
  // Often a perfect square or a neighbour of one, where off-by-one errors live.
  if (*rc::gen::inRange(0, 3) == 0) {
    const U r = U(lo) >> (*rc::gen::inRange(0, 64));
    n = r * r - U(*rc::gen::inRange(0, 2)) + (r == 0 ? 1 : 0);
  }
  const U root = isqrt(n);
  RC_ASSERT(big(root) == sqrt(big(n)));
}

RC_GTEST_PROP(PerimeterBoundsProperty, BracketsEveryEdgeExactly, ()) {
  const Ring ring = gen_ring(gen_grid(), 10);
  cpp_int lo = 0, hi = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % ring.size()];
    const cpp_int dx = cpp_int(b.x) - a.x, dy = cpp_int(b.y) - a.y;
    const cpp_int squared = dx * dx + dy * dy;
    const cpp_int root = sqrt(squared);
    lo += root;
    hi += root * root == squared ? root : root + 1;
  }
  const PerimeterBounds b = perimeter_bounds(ring);
  RC_ASSERT(big(b.lo) == lo);
  RC_ASSERT(big(b.hi) == hi);
  RC_ASSERT(b.lo <= b.hi);
  RC_ASSERT(b.hi - b.lo <= Int128(ring.size()));
}

}  // namespace
}  // namespace edgeland::test
