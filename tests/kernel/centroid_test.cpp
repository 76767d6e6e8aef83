// centroid.hpp: the exact centroid of a polygon set, against an independent reference: the
// area-weighted mean of triangle centroids (a + b + c) / 3 over triangulate()'s triangles, in
// Boost rationals (the shoelace moment formula of centroid.cpp is not used there).
#include "edgeland/kernel/centroid.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <boost/multiprecision/cpp_int.hpp>

#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/triangulate.hpp"
#include "edgeland/kernel/validate.hpp"
#include "support/big_int.hpp"
#include "support/generators.hpp"

namespace edgeland::testing {
namespace {

using boost::multiprecision::cpp_int;
using boost::multiprecision::cpp_rational;

constexpr std::int64_t B = kCoordBound;

using edgeland::test::big;

struct RationalXY {
  cpp_rational x, y;
};

// Sum of area_t * (a + b + c) / 3 over the triangles, divided by the total area.
RationalXY reference_centroid(const PolygonSet& set) {
  cpp_rational area = 0, mx = 0, my = 0;
  for (const Polygon& p : set) {
    for (const Triangle& t : triangulate(p)) {
      const Point64 a = p[t.a], b = p[t.b], c = p[t.c];
      const cpp_rational twice =
          cpp_int(b.x - a.x) * (c.y - a.y) - cpp_int(b.y - a.y) * (c.x - a.x);
      area += twice;
      mx += twice * (cpp_int(a.x) + b.x + c.x) / 3;
      my += twice * (cpp_int(a.y) + b.y + c.y) / 3;
    }
  }
  return {mx / area, my / area};
}

bool lowest_terms(const RationalPoint& r) {
  return gcd(gcd(big(r.x_num), big(r.y_num)), big(r.den)) == 1 && r.den > 0;
}

bool equals(const RationalPoint& r, const RationalXY& ref) {
  return cpp_rational(big(r.x_num), big(r.den)) == ref.x &&
         cpp_rational(big(r.y_num), big(r.den)) == ref.y;
}

TEST(Centroid, SquareAndTriangle) {
  EXPECT_EQ(centroid({{{0, 0}, {2, 0}, {2, 2}, {0, 2}}}), (RationalPoint{1, 1, 1}));
  EXPECT_EQ(centroid({{{0, 0}, {1, 0}, {0, 1}}}), (RationalPoint{1, 1, 3}));
  // Straight vertices change nothing.
  EXPECT_EQ(centroid({{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 1}}}), (RationalPoint{1, 1, 1}));
}

TEST(Centroid, SetWeighsItsMembersByArea) {
  // A 2x2 square centred at (1, 1) and a 4x2 rectangle centred at (4, 1), areas 4 and 8:
  // x = (4*1 + 8*4) / 12 = 3, y = 1.
  const PolygonSet set{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{2, 0}, {6, 0}, {6, 2}, {2, 2}}};
  EXPECT_EQ(centroid(set), (RationalPoint{3, 1, 1}));
}

TEST(Centroid, FullCoordinateRange) {
  // Every moment term near its bound 4 B^3 (the checked build traps any overflow).
  EXPECT_EQ(centroid({{{-B, -B}, {B, -B}, {B, B}, {-B, B}}}), (RationalPoint{0, 0, 1}));
  const PolygonSet corner{{{B - 1, B - 1}, {B, B - 1}, {B, B}}};
  EXPECT_TRUE(equals(centroid(corner), reference_centroid(corner)));
  const PolygonSet sliver{{{-B, -B}, {B, B - 1}, {B, B}}};
  EXPECT_TRUE(equals(centroid(sliver), reference_centroid(sliver)));
}

TEST(Centroid, RejectsSetsWithoutPositiveArea) {
  EXPECT_THROW(centroid({}), NonPositiveArea);
  try {
    centroid({{{0, 0}, {0, 1}, {1, 0}}});  // clockwise
    FAIL() << "no error";
  } catch (const NonPositiveArea& e) {
    EXPECT_EQ(e.twice_area, -1);
  }
  EXPECT_THROW(centroid({{{0, 0}, {1, 1}, {2, 2}}}), NonPositiveArea);  // flat
  try {
    centroid({{{0, 0}, {1, 0}, {0, 1}}, {{0, 0}, {B + 1, 0}, {0, 1}}});
    FAIL() << "no error";
  } catch (const CoordinateOutOfRange& e) {
    EXPECT_EQ(e.operand, Operand::kPolygon);
    EXPECT_EQ(e.polygon, 1u);
    EXPECT_EQ(e.vertex, 1u);
  }
}

RC_GTEST_PROP(CentroidProperty, EqualsTheTriangleReference, ()) {
  const std::int64_t r = *rc::gen::element<std::int64_t>(5, 100, 1'000'000, B / 4);
  const Point64 c{*test::gen::coord(-B + 2 * r, B - 2 * r),
                  *test::gen::coord(-B + 2 * r, B - 2 * r)};
  const PolygonSet set = *test::gen::polygon_set(c, r);
  RC_PRE(!set.empty());
  const RationalPoint got = centroid(set);
  RC_ASSERT(lowest_terms(got));
  RC_ASSERT(equals(got, reference_centroid(set)));
}

RC_GTEST_PROP(CentroidProperty, MovesWithTheSet, ()) {
  // Translating the set by t moves the centroid by exactly t.
  const PolygonSet set = *test::gen::polygon_set({0, 0}, 1000);
  RC_PRE(!set.empty());
  const std::int64_t dx = *test::gen::coord(-1'000'000, 1'000'000);
  const std::int64_t dy = *test::gen::coord(-1'000'000, 1'000'000);
  const RationalPoint a = centroid(set), b = centroid(*test::translation(dx, dy).apply(set));
  RC_ASSERT(b.den == a.den);
  RC_ASSERT(b.x_num == a.x_num + Int128(dx) * a.den);
  RC_ASSERT(b.y_num == a.y_num + Int128(dy) * a.den);
}

}  // namespace
}  // namespace edgeland::testing
