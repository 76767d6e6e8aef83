// area.hpp: exact twice-signed-area and ring orientation (thesis 2.2).
#include "edgeland/kernel/area.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>

#include "exact_reference.hpp"
#include "random_geometry.hpp"
#include "support/big_int.hpp"

namespace edgeland::test {
namespace {

TEST(TwiceSignedArea, FullRangeSquareIsExact) {
  const Ring ccw{{-B, -B}, {B, -B}, {B, B}, {-B, B}};
  const Int128 side = 2 * Int128(B);
  EXPECT_EQ(twice_signed_area(ccw), 2 * side * side);  // about 2^65: only fits in 128 bits
  Ring cw(ccw.rbegin(), ccw.rend());
  EXPECT_EQ(twice_signed_area(cw), -2 * side * side);
  EXPECT_EQ(ring_orientation(ccw), Orientation::kCounterClockwise);
  EXPECT_EQ(ring_orientation(cw), Orientation::kClockwise);
}

TEST(TwiceSignedArea, UnitTriangleHasOddTwiceArea) {
  // Area 1/2: the reason the kernel reports twice the area.
  EXPECT_EQ(twice_signed_area(Ring{{0, 0}, {1, 0}, {0, 1}}), 1);
}

TEST(TwiceSignedArea, DegenerateRingsHaveZeroArea) {
  EXPECT_EQ(twice_signed_area(Ring{}), 0);
  EXPECT_EQ(twice_signed_area(Ring{{B, B}, {-B, -B}}), 0);
  EXPECT_EQ(twice_signed_area(Ring{{-B, -B}, {0, 0}, {B, B}}), 0);
  EXPECT_EQ(ring_orientation(Ring{{-B, -B}, {0, 0}, {B, B}}), Orientation::kCollinear);
}

TEST(TwiceSignedArea, FigureEightWeighsLobesByWinding) {
  // Bow-tie: the two lobes wind in opposite directions and cancel.
  EXPECT_EQ(twice_signed_area(Ring{{0, 0}, {2, 2}, {2, 0}, {0, 2}}), 0);
}

TEST(TwiceSignedArea, SetSumsItsMembers) {
  const PolygonSet set{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{2, 0}, {3, 0}, {2, 1}}};
  EXPECT_EQ(twice_signed_area(set), 8 + 1);
}

RC_GTEST_PROP(TwiceSignedAreaProperty, EqualsCppIntShoelace, ()) {
  const Ring ring = gen_ring(gen_grid(), 12);
  RC_ASSERT(big(twice_signed_area(ring)) == ref_twice_area(ring));
  RC_ASSERT(static_cast<int>(ring_orientation(ring)) == sgn(ref_twice_area(ring)));
}

RC_GTEST_PROP(TwiceSignedAreaProperty, ReversalNegatesAndRotationKeeps, ()) {
  const Ring ring = gen_ring(gen_grid(), 12);
  const Ring reversed(ring.rbegin(), ring.rend());
  RC_ASSERT(twice_signed_area(reversed) == -twice_signed_area(ring));
  const auto k = *rc::gen::inRange<std::size_t>(0, ring.size());
  RC_ASSERT(twice_signed_area(rotated(ring, k)) == twice_signed_area(ring));
}

}  // namespace
}  // namespace edgeland::test
