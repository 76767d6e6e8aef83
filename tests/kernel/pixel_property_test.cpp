// segment_meets_pixel against a reference written straight from the definition: the closed
// segment a + t (b - a), t in [0, 1], has a point in the half-open square
// [c - 1/2, c + 1/2)^2. The reference intersects parameter intervals with open and closed ends
// in exact rationals; the kernel clips the closed square (Liang-Barsky) and then removes the
// open sides, after a separating-axis prefilter. Small coordinates make the cases where a
// segment grazes a corner or runs along a side frequent.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <string>

#include "edgeland/kernel/pixel.hpp"
#include "edgeland/kernel/point.hpp"
#include "exact_reference.hpp"

namespace edgeland {
namespace {

using test::cpp_rational;

// An interval of t with each end open or closed.
struct Interval {
  cpp_rational lo{0}, hi{1};
  bool lo_open = false, hi_open = false;
  bool empty = false;
  void at_least(const cpp_rational& v, bool open) {
    if (v > lo || (v == lo && open)) {
      lo = v;
      lo_open = open;
    }
  }
  void at_most(const cpp_rational& v, bool open) {
    if (v < hi || (v == hi && open)) {
      hi = v;
      hi_open = open;
    }
  }
  bool has_points() const { return !empty && (lo < hi || (lo == hi && !lo_open && !hi_open)); }
};

// lo <= a + t * d < hi (the coordinate's half-open range; <= hi when hi_closed), as
// constraints on t.
void constrain(Interval& t, std::int64_t a, std::int64_t d, const cpp_rational& lo,
               const cpp_rational& hi, bool hi_closed = false) {
  if (d == 0) {
    const cpp_rational v(a);
    if (!(lo <= v && (v < hi || (hi_closed && v == hi)))) t.empty = true;
    return;
  }
  const cpp_rational at_lo = (lo - a) / d, at_hi = (hi - a) / d;
  if (d > 0) {
    t.at_least(at_lo, false);
    t.at_most(at_hi, !hi_closed);
  } else {
    t.at_most(at_lo, false);
    t.at_least(at_hi, !hi_closed);
  }
}

bool reference_meets(const Segment& s, Point64 c, bool closed = false) {
  const cpp_rational half(1, 2);
  Interval t;
  constrain(t, s.a.x, s.b.x - s.a.x, cpp_rational(c.x) - half, cpp_rational(c.x) + half, closed);
  constrain(t, s.a.y, s.b.y - s.a.y, cpp_rational(c.y) - half, cpp_rational(c.y) + half, closed);
  return t.has_points();
}

// The closed square [c - 1/2, c + 1/2]^2 (snap rounding's "near a pixel").
bool reference_meets_closed(const Segment& s, Point64 c) { return reference_meets(s, c, true); }

// f(s) for every segment with both ends in [-3, 3]^2 (degenerate ones included).
template <class F>
void for_each_small_segment(F&& f) {
  for (std::int64_t ax = -3; ax <= 3; ++ax)
    for (std::int64_t ay = -3; ay <= 3; ++ay)
      for (std::int64_t bx = -3; bx <= 3; ++bx)
        for (std::int64_t by = -3; by <= 3; ++by) f(Segment{{ax, ay}, {bx, by}});
}

std::string describe(const Segment& s) {
  return "(" + std::to_string(s.a.x) + "," + std::to_string(s.a.y) + ")-(" + std::to_string(s.b.x) +
         "," + std::to_string(s.b.y) + ")";
}

rc::Gen<Point64> near_point(std::int64_t reach) {
  return rc::gen::apply(
      [](std::int64_t x, std::int64_t y) {
        return Point64{x, y};
      },
      rc::gen::inRange<std::int64_t>(-reach, reach + 1),
      rc::gen::inRange<std::int64_t>(-reach, reach + 1));
}

// Every segment with both ends in [-3, 3]^2 against the pixel of the origin: all the ways of
// grazing a corner, running along a side's line or stopping on it.
TEST(SegmentMeetsPixel, AgreesWithTheDefinitionForEverySmallSegment) {
  std::size_t meeting = 0, total = 0;
  for_each_small_segment([&](const Segment& s) {
    const bool expected = reference_meets(s, {0, 0});
    EXPECT_EQ(segment_meets_pixel(s, {0, 0}), expected) << describe(s);
    meeting += expected;
    ++total;
  });
  EXPECT_GT(meeting, 0u);
  EXPECT_LT(meeting, total);
}

RC_GTEST_PROP(SegmentMeetsPixel, AgreesWithTheDefinitionNearThePixel, ()) {
  const Point64 c = *near_point(2);
  const Segment s{*near_point(6), *near_point(6)};
  RC_ASSERT(segment_meets_pixel(s, c) == reference_meets(s, c));
}

RC_GTEST_PROP(SegmentMeetsPixel, AgreesWithTheDefinitionForLongSegments, ()) {
  // Long segments passing within a unit or two of a pixel anywhere in the range.
  const std::int64_t span = *rc::gen::element<std::int64_t>(1000, 1 << 20, kCoordBound);
  const Point64 a = *rc::gen::apply(
      [](std::int64_t x, std::int64_t y) {
        return Point64{x, y};
      },
      rc::gen::inRange<std::int64_t>(-span, span + 1),
      rc::gen::inRange<std::int64_t>(-span, span + 1));
  const Point64 b = *rc::gen::apply(
      [](std::int64_t x, std::int64_t y) {
        return Point64{x, y};
      },
      rc::gen::inRange<std::int64_t>(-span, span + 1),
      rc::gen::inRange<std::int64_t>(-span, span + 1));
  const Segment s{a, b};
  // A point on the segment's line at a random parameter, rounded, then nudged.
  const std::int64_t k = *rc::gen::inRange<std::int64_t>(0, 65);
  const Point64 on{a.x + static_cast<std::int64_t>(Int128(b.x - a.x) * k / 64),
                   a.y + static_cast<std::int64_t>(Int128(b.y - a.y) * k / 64)};
  const Point64 c{on.x + *rc::gen::inRange<std::int64_t>(-2, 3),
                  on.y + *rc::gen::inRange<std::int64_t>(-2, 3)};
  RC_PRE(in_range(c));
  RC_ASSERT(segment_meets_pixel(s, c) == reference_meets(s, c));
}

TEST(SegmentMeetsClosedPixel, AgreesWithTheDefinitionForEverySmallSegment) {
  std::size_t meeting = 0, only_closed = 0;
  for_each_small_segment([&](const Segment& s) {
    const bool expected = reference_meets_closed(s, {0, 0});
    EXPECT_EQ(segment_meets_closed_pixel(s, {0, 0}), expected) << describe(s);
    meeting += expected;
    only_closed += expected && !reference_meets(s, {0, 0});
  });
  EXPECT_GT(meeting, 0u);
  EXPECT_GT(only_closed, 0u);  // segments touching only the top or right side are among them
}

RC_GTEST_PROP(SegmentMeetsClosedPixel, AgreesWithTheDefinitionNearThePixel, ()) {
  const Point64 c = *near_point(2);
  const Segment s{*near_point(6), *near_point(6)};
  RC_ASSERT(segment_meets_closed_pixel(s, c) == reference_meets_closed(s, c));
}

TEST(SegmentMeetsClosedPixel, FullRangeSegmentsAndTheirCorners) {
  // The longest segments: the full-range diagonal passes through every pixel centre (c, c) and
  // grazes the closed pixels of (c, c + 1) at their corners (c + 1/2, c + 1/2); the other
  // diagonal's neighbours (c + 1, -c) are touched only at (c + 1/2, -c - 1/2).
  const std::int64_t B = kCoordBound;
  const Segment up{{-B, -B}, {B, B}}, down{{-B, B}, {B, -B}};
  for (const std::int64_t c : {-B, std::int64_t{-12345}, std::int64_t{0}, B - 2}) {
    EXPECT_TRUE(segment_meets_closed_pixel(up, {c, c}));
    EXPECT_TRUE(segment_meets_closed_pixel(up, {c, c + 1}));
    EXPECT_FALSE(segment_meets_closed_pixel(up, {c, c + 2}));
    EXPECT_TRUE(segment_meets_closed_pixel(down, {c + 1, -c}));
    EXPECT_FALSE(segment_meets_closed_pixel(down, {c + 2, -c}));
  }
}

TEST(SegmentMeetsPixel, HalfOpenCorners) {
  // The pixel of the origin is [-1/2, 1/2)^2: its bottom-left corner belongs to it, its
  // top-right corner to a neighbour.
  EXPECT_TRUE(segment_meets_pixel({{0, 5}, {0, -5}}, {0, 0}));   // through the centre
  EXPECT_TRUE(segment_meets_pixel({{-1, 0}, {0, -1}}, {0, 0}));  // x + y = -1: only (-1/2, -1/2)
  EXPECT_FALSE(segment_meets_pixel({{0, 1}, {1, 0}}, {0, 0}));   // x + y = 1: only (1/2, 1/2)
  EXPECT_TRUE(segment_meets_pixel({{-1, 0}, {1, 1}}, {0, 0}));   // y = (x + 1) / 2 crosses it
  EXPECT_FALSE(segment_meets_pixel({{1, -3}, {1, 3}}, {0, 0}));  // x = 1: the next column
}

}  // namespace
}  // namespace edgeland
