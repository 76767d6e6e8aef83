// angle_less and angle_less_branch_free (angle.hpp) against an independent exact formulation:
// octant classes (the four axis rays and the four open quadrants between them, counter-clockwise
// from angle 0), then, in one open quadrant, the exact cross product. Directions are differences of
// generated points, from tiny grids up to the full coordinate range.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "edgeland/kernel/angle.hpp"
#include "exact_reference.hpp"
#include "random_geometry.hpp"

namespace edgeland::test {
namespace {

int octant(Point64 d) {
  if (d.y == 0) return d.x > 0 ? 0 : 4;
  if (d.x == 0) return d.y > 0 ? 2 : 6;
  if (d.y > 0) return d.x > 0 ? 1 : 3;
  return d.x < 0 ? 5 : 7;
}

bool reference_less(Point64 a, Point64 b) {
  if (octant(a) != octant(b)) return octant(a) < octant(b);
  // Same axis ray: equal angles. Same open quadrant: b is counter-clockwise of a.
  return cpp_int(a.x) * b.y - cpp_int(a.y) * b.x > 0;
}

Point64 difference(Point64 from, Point64 to) { return {to.x - from.x, to.y - from.y}; }

RC_GTEST_PROP(AngleLessProperty, MatchesOctantsThenCrossProduct, ()) {
  const Grid g = gen_grid();
  const Point64 a = difference(gen_point(g), gen_point(g)),
                b = difference(gen_point(g), gen_point(g));
  const Point64 zero{0, 0};
  RC_PRE(a != zero && b != zero);  // directions are nonzero
  RC_ASSERT(angle_less(a, b) == reference_less(a, b));
  RC_ASSERT(angle_less_branch_free(a, b) == reference_less(a, b));
  RC_ASSERT(!(angle_less(a, b) && angle_less(b, a)));
}

TEST(AngleLess, OrdersTheEightCompassDirections) {
  const Point64 compass[] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      EXPECT_EQ(angle_less(compass[i], compass[j]), i < j) << i << " " << j;
      EXPECT_EQ(angle_less_branch_free(compass[i], compass[j]), i < j) << i << " " << j;
    }
  EXPECT_FALSE(angle_less({2, 0}, {1, 0}));  // one ray: neither before the other
  EXPECT_FALSE(angle_less({1, 0}, {2, 0}));
}

}  // namespace
}  // namespace edgeland::test
