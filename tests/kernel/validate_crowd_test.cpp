// validate() where very many rings meet at one point (issue 16: a hostile file of N identical
// squares took minutes, since the sweep placed the edges starting at one point one by one).
// Each case is decided against what the shapes are by construction; the ctest time-out
// (the kernel tests' 300 s) is what catches a quadratic sweep: 10^5 rings here took an
// estimated 400 s before and a few seconds after.
#include <gtest/gtest.h>

#include <cstdint>

#include "edgeland/kernel/validate.hpp"

namespace edgeland {
namespace {

constexpr std::size_t kCrowd = 100'000;

// N copies of one square: every two overlap, so the first report names polygons 0 and 1,
// and the check stops at its limit of kDefaultMaxViolations, each naming a new member.
TEST(ValidateCrowd, IdenticalSquaresAreReportedWithoutQuadraticWork) {
  const Polygon square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const PolygonSet copies(kCrowd, square);
  const ValidationReport report = validate(copies);
  ASSERT_EQ(report.violations.size(), kDefaultMaxViolations);
  for (const Violation& v : report.violations) {
    EXPECT_EQ(v.rule, Rule::kOverlappingInteriors);
    EXPECT_NE(v.other_polygon, kNone);
    EXPECT_NE(v.polygon, v.other_polygon);
  }
  EXPECT_EQ(report.violations.front().polygon, 0u);
  EXPECT_EQ(report.violations.front().other_polygon, 1u);
}

// A fan of N thin triangles around the origin, each sharing an edge with the next: a valid
// set whose every member meets the others at one point. Listed in a scrambled order
// (i * 7919 mod N, a permutation as 7919 is prime to N), so the edges leaving the origin
// come to the sweep far from their order around it.
PolygonSet fan(std::size_t n) {
  PolygonSet triangles;
  triangles.reserve(n);
  const std::int64_t reach = 1'000'000'000;
  for (std::size_t i = 0; i < n; ++i) {
    const auto y = static_cast<std::int64_t>(i * 7919 % n);
    triangles.push_back(Polygon{{0, 0}, {reach, y}, {reach, y + 1}});
  }
  return triangles;
}

TEST(ValidateCrowd, FanAroundOnePointIsValid) { EXPECT_TRUE(validate(fan(kCrowd)).ok()); }

// The same fan with one triangle doubled: exactly that overlap is found.
TEST(ValidateCrowd, FanWithOneDoubledTriangleNamesIt) {
  PolygonSet triangles = fan(kCrowd);
  triangles.push_back(triangles[kCrowd / 2]);
  const ValidationReport report = validate(triangles);
  ASSERT_EQ(report.violations.size(), 1u);
  EXPECT_EQ(report.violations.front().rule, Rule::kOverlappingInteriors);
  EXPECT_EQ(report.violations.front().polygon, kCrowd / 2);
  EXPECT_EQ(report.violations.front().other_polygon, kCrowd);
}

}  // namespace
}  // namespace edgeland
