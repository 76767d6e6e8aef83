// Large inputs whose shape defeated a candidate search (issue 16, point 1): two combs of 10^4
// teeth 10^8 long and 40 wide, 80 apart. The segment grid, sized for spikes, put thousands of
// teeth in each cell and then either paired them all (10^8 pairs) or, with finer cells,
// registered each tooth in thousands of cells (gigabytes); either ran into clip_tests' time-out.
// Candidate searches now compare their counted work with the run index's. Speed itself is
// measured in bench/ (run_scale.sh); this checks the results exactly.
#include <gtest/gtest.h>

#include "checked_clip.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/validate.hpp"

namespace edgeland::test {
namespace {

constexpr std::int64_t kTeeth = 10000, kWidth = 40, kPitch = 80, kLength = 100000000,
                       kBase = 1000000;

// A base bar [0, teeth * pitch] x [0, base] with teeth [pitch * t, pitch * t + width] x
// [base, length], moved by (dx, dy); one counter-clockwise polygon.
Polygon comb(std::int64_t dx, std::int64_t dy) {
  Polygon p{{dx, dy}, {dx + kTeeth * kPitch, dy}, {dx + kTeeth * kPitch, dy + kBase}};
  for (std::int64_t t = kTeeth - 1; t >= 0; --t) {
    const std::int64_t x = dx + t * kPitch;
    for (Point64 q : {Point64{x + kWidth, dy + kBase}, Point64{x + kWidth, dy + kLength},
                      Point64{x, dy + kLength}, Point64{x, dy + kBase}})
      if (q != p.back()) p.push_back(q);
  }
  p.pop_back();  // (dx, dy + base) lies on the edge back to the start
  return p;
}

TEST(ScaleShapes, LongCombTeethCrossingABaseBar) {
  // B is A moved by (20, length / 2): B's bar crosses every tooth of A, and B's teeth overlap
  // the upper half of A's, 20 wide each.
  const PolygonSet a{comb(0, 0)}, b{comb(20, kLength / 2)};
  ASSERT_TRUE(validate(a, 1).ok());
  const Int128 area_a =
      Int128(kTeeth * kPitch) * kBase + Int128(kTeeth * kWidth) * (kLength - kBase);
  // A's teeth under B's bar (the first tooth only from x = 20), then A's and B's teeth side by
  // side from B's teeth's foot to A's tips.
  const Int128 area_common =
      Int128(kBase) * (kWidth * kTeeth - 20) + Int128(20 * kTeeth) * (kLength / 2 - kBase);
  const Outcome common = run_clip(ClipOp::kIntersection, a, b);
  ASSERT_TRUE(common.ok()) << common.error.substr(0, 300);
  EXPECT_EQ(common.result->stats.vertices_snapped, 0u);
  EXPECT_EQ(twice_signed_area(common.result->polygons), 2 * area_common);
  const Outcome rest = run_clip(ClipOp::kDifference, a, b);
  ASSERT_TRUE(rest.ok()) << rest.error.substr(0, 300);
  EXPECT_EQ(twice_signed_area(rest.result->polygons), 2 * (area_a - area_common));
}

}  // namespace
}  // namespace edgeland::test
