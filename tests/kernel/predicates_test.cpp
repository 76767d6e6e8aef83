#include "edgeland/kernel/predicates.hpp"

#include <gtest/gtest.h>

namespace edgeland {
namespace {

constexpr std::int64_t B = kCoordBound;

TEST(Orientation, ExtremeCornersAreExact) {
  // The determinant here is about 2^65: it only fits because the kernel computes in 128 bits.
  EXPECT_EQ(orientation({-B, -B}, {B, -B}, {B, B}), Orientation::kCounterClockwise);
  EXPECT_EQ(orientation({-B, -B}, {B, B}, {B, -B}), Orientation::kClockwise);
  EXPECT_EQ(orientation({-B, -B}, {0, 0}, {B, B}), Orientation::kCollinear);
  EXPECT_EQ(orient_det({-B, -B}, {B, -B}, {B, B}), Int128(2 * B) * Int128(2 * B));
}

TEST(Orientation, OffByOneNearTheBoundIsSeen) {
  EXPECT_EQ(orientation({-B, -B}, {B, B}, {B - 1, B}), Orientation::kCounterClockwise);
  EXPECT_EQ(orientation({-B, -B}, {B, B}, {B, B - 1}), Orientation::kClockwise);
}

TEST(Intersect, ProperCrossingGivesExactRational) {
  const auto r = intersect({{0, 0}, {3, 1}}, {{0, 1}, {3, 0}});
  ASSERT_EQ(r.relation, SegmentRelation::kCrossing);
  // The crossing is (3/2, 1/2).
  EXPECT_EQ(r.point.x_num * 2, r.point.den * 3);
  EXPECT_EQ(r.point.y_num * 2, r.point.den * 1);
  EXPECT_EQ(round_to_grid(r.point), (Point64{2, 1}));  // halves round up
}

TEST(Intersect, CollinearOverlapReportsItsEnds) {
  const auto r = intersect({{0, 0}, {10, 0}}, {{12, 0}, {4, 0}});
  ASSERT_EQ(r.relation, SegmentRelation::kOverlapping);
  EXPECT_EQ(r.overlap_from, (Point64{4, 0}));
  EXPECT_EQ(r.overlap_to, (Point64{10, 0}));
}

TEST(Intersect, TouchAtEndpointAndTouchOnInterior) {
  EXPECT_EQ(intersect({{0, 0}, {2, 2}}, {{2, 2}, {4, 0}}).relation, SegmentRelation::kTouching);
  const auto r = intersect({{0, 0}, {4, 0}}, {{2, 0}, {2, 5}});
  ASSERT_EQ(r.relation, SegmentRelation::kTouching);
  EXPECT_EQ(round_to_grid(r.point), (Point64{2, 0}));
  EXPECT_EQ(intersect({{0, 0}, {4, 0}}, {{5, 0}, {9, 0}}).relation, SegmentRelation::kDisjoint);
}

TEST(RoundToGrid, HalvesRoundTowardPlusInfinity) {
  EXPECT_EQ(round_to_grid({1, 2, 2}), (Point64{1, 1}));     // (0.5, 1) -> (1, 1)
  EXPECT_EQ(round_to_grid({-1, -3, 2}), (Point64{0, -1}));  // (-0.5, -1.5) -> (0, -1)
  EXPECT_EQ(round_to_grid({-2, 7, 3}), (Point64{-1, 2}));   // (-0.67, 2.33) -> (-1, 2)
}

}  // namespace
}  // namespace edgeland
