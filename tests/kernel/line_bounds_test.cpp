// line_y_at / line_x_at (kernel/line_bounds.hpp) against the exact rational y of the line, by
// cross-multiplication in 128 bits: lo <= y <= hi, lo = floor(y), hi - lo <= 1, exact at the ends
// and on flat lines (floor(y) itself rests on formulas::crossing_numerator, theorem
// shape_cut_int128).
#include "edgeland/kernel/line_bounds.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <utility>

#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"

namespace edgeland {
namespace {

// y(x) = a.y + (x - a.x) (b.y - a.y) / (b.x - a.x), with a.x < b.x: lo <= y iff
// (lo - a.y) (b.x - a.x) <= (x - a.x) (b.y - a.y), all products below 2^66 in magnitude.
void expect_bounds(Point64 a, Point64 b, std::int64_t x) {
  const IntegerRange r = line_y_at(a, b, x);
  if (a.x > b.x) std::swap(a, b);
  const Int128 den = Int128(b.x) - a.x, num = (Int128(x) - a.x) * (Int128(b.y) - a.y);
  RC_ASSERT((Int128(r.lo) - a.y) * den <= num);     // lo <= y
  RC_ASSERT(num < (Int128(r.lo) + 1 - a.y) * den);  // y < lo + 1: lo is the floor
  RC_ASSERT(num <= (Int128(r.hi) - a.y) * den);     // y <= hi
  RC_ASSERT(r.hi - r.lo <= 1);
}

std::int64_t coordinate() {
  return *rc::gen::oneOf(rc::gen::inRange<std::int64_t>(-kCoordBound, kCoordBound + 1),
                         rc::gen::inRange<std::int64_t>(-40, 41));
}

RC_GTEST_PROP(LineBounds, BoundTheLinesYAtEveryXBetweenTheEnds, ()) {
  const Point64 a{coordinate(), coordinate()};
  const Point64 b{coordinate(), coordinate()};
  RC_PRE(a.x != b.x);
  const std::int64_t x = *rc::gen::inRange(std::min(a.x, b.x), std::max(a.x, b.x) + 1);
  expect_bounds(a, b, x);
  // The swapped axes give the same bounds on x at y.
  const IntegerRange s = line_x_at({a.y, a.x}, {b.y, b.x}, x), r = line_y_at(a, b, x);
  RC_ASSERT(s.lo == r.lo && s.hi == r.hi);
}

TEST(LineBounds, ExactAtTheEndsAndOnFlatLines) {
  const Point64 a{-kCoordBound, 7}, b{kCoordBound, -kCoordBound};
  EXPECT_EQ(line_y_at(a, b, a.x).lo, 7);
  EXPECT_EQ(line_y_at(a, b, a.x).hi, 7);
  EXPECT_EQ(line_y_at(a, b, b.x).lo, -kCoordBound);
  EXPECT_EQ(line_y_at(a, b, b.x).hi, -kCoordBound);
  EXPECT_EQ(line_y_at({0, 5}, {100, 5}, 37).lo, 5);
  EXPECT_EQ(line_y_at({0, 5}, {100, 5}, 37).hi, 5);
  // y = -1/2 at x = 1 on the line from (0, 0) to (2, -1): floor -1.
  EXPECT_EQ(line_y_at({0, 0}, {2, -1}, 1).lo, -1);
  EXPECT_EQ(line_y_at({2, -1}, {0, 0}, 1).lo, -1);
  EXPECT_EQ(line_x_at({0, 0}, {-1, 2}, 1).lo, -1);
}

}  // namespace
}  // namespace edgeland
