// Cases for kernel/ lines the rest of the suite did not reach (issue 18, scripts/coverage.sh).
// Each asserts a documented property; expectations are worked out by hand from the headers'
// contracts, not taken from a run.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland {
namespace {

// bbox.hpp: the box of a set is the componentwise minimum and maximum over all members.
TEST(BoundingBox, OfASetSpansEveryMember) {
  const PolygonSet set{{{0, 0}, {4, 0}, {0, 3}}, {{-2, 5}, {1, 5}, {1, 9}}};
  const std::optional<Box64> box = bounding_box(set);
  ASSERT_TRUE(box.has_value());
  EXPECT_EQ(*box, (Box64{{-2, 0}, {4, 9}}));
  EXPECT_FALSE(*box == (Box64{{-2, 0}, {4, 8}}));
}

// errors.hpp: the message names the operand and carries validate()'s description; the
// fields repeat the violation's data.
TEST(CoordinateOutOfRange, NamesTheQueryOperand) {
  const Point64 where{kCoordBound + 1, -3};
  const CoordinateOutOfRange e(Operand::kQuery, 0, 0, 0, where);
  EXPECT_EQ(std::string(e.what()), "invalid query: " + e.violation.describe());
  EXPECT_EQ(e.operand, Operand::kQuery);
  EXPECT_EQ(e.violation.rule, Rule::kCoordinateOutOfRange);
  EXPECT_EQ(e.where, where);
}

TEST(CoordinateOutOfRange, NamesTheRingsOperand) {
  const Point64 where{0, -kCoordBound - 1};
  const CoordinateOutOfRange e(Operand::kRings, 3, 0, 7, where);
  EXPECT_EQ(std::string(e.what()), "invalid rings: " + e.violation.describe());
  EXPECT_EQ(e.polygon, 3u);
  EXPECT_EQ(e.ring, 0u);
  EXPECT_EQ(e.vertex, 7u);
  EXPECT_EQ(e.violation.polygon, 3u);
  EXPECT_EQ(e.violation.edge, 7u);
}

// errors.hpp: a ring other than the exterior (0) is a field and is named in the message, after
// the polygon; a Violation has no ring, so violation.describe() cannot say it.
TEST(CoordinateOutOfRange, NamesAHoleRingInTheMessage) {
  const Point64 where{23, kCoordBound + 1};
  const CoordinateOutOfRange e(Operand::kRings, 1, 2, 0, where);
  EXPECT_EQ(e.ring, 2u);
  EXPECT_EQ(e.violation.rule, Rule::kCoordinateOutOfRange);
  EXPECT_EQ(std::string(e.what()),
            "invalid rings: coordinate-out-of-range: polygon 1 ring 2 vertex 0 at (23 2147483648)");
}

// errors.hpp: validate()'s violations are of single rings, so one made into the error has ring 0.
TEST(CoordinateOutOfRange, FromAViolationIsRingZero) {
  const ValidationReport r = validate(Polygon{{0, 0}, {kCoordBound + 1, 0}, {0, 5}});
  ASSERT_FALSE(r.ok());
  const CoordinateOutOfRange e(Operand::kSubject, r.violations.front());
  EXPECT_EQ(e.ring, 0u);
  EXPECT_EQ(e.vertex, 1u);
  EXPECT_EQ(std::string(e.what()),
            "invalid subject: coordinate-out-of-range: polygon 0 vertex 1 at (2147483648 0)");
}

// errors.hpp: an inverted box is an InvalidInput of rule inverted-box keeping the box; the
// message names both corners and the axis (or axes) in which min exceeds max.
TEST(InvalidBox, KeepsTheBoxAndNamesTheInvertedAxes) {
  const Box64 in_x{{5, 0}, {0, 5}};
  const InvalidBox e(Operand::kClip, in_x);
  EXPECT_EQ(e.box, in_x);
  EXPECT_EQ(e.operand, Operand::kClip);
  EXPECT_EQ(e.violation.rule, Rule::kInvertedBox);
  EXPECT_EQ(e.violation.where, (Point64{5, 0}));
  EXPECT_EQ(std::string(e.what()), "invalid clip: inverted-box: min (5 0) exceeds max (0 5) in x");
  EXPECT_EQ(e.violation.describe(), "inverted-box: min corner at (5 0)");
  EXPECT_EQ(std::string(InvalidBox(Operand::kQuery, Box64{{0, 5}, {5, 0}}).what()),
            "invalid query: inverted-box: min (0 5) exceeds max (5 0) in y");
  EXPECT_EQ(std::string(InvalidBox(Operand::kClip, Box64{{5, 5}, {0, -1}}).what()),
            "invalid clip: inverted-box: min (5 5) exceeds max (0 -1) in x and y");
  const InvalidInput* base = &e;
  EXPECT_EQ(base->what(), e.what());
}

// validate.hpp: describe() words an edge given alone like the pair form
// "self-intersection: polygon 0 edges 0 and 2 at (5 5)". No rule of validate() reports a
// lone edge, but a Violation is a plain public struct.
TEST(ViolationDescribe, NamesALoneEdge) {
  Violation v;
  v.rule = Rule::kNotCounterClockwise;
  v.polygon = 2;
  v.edge = 5;
  v.where = {7, -1};
  EXPECT_EQ(v.describe(), "not-counter-clockwise: polygon 2 edge 5 at (7 -1)");
}

// wkt_writer.hpp: one polygon as "POLYGON ((...))", its ring closed by repeating the first
// vertex as WKT requires.
TEST(ToWkt, PolygonClosesItsRing) {
  EXPECT_EQ(to_wkt(Polygon{{0, 0}, {4, 0}, {0, -3}}), "POLYGON ((0 0, 4 0, 0 -3, 0 0))");
  EXPECT_EQ(to_wkt(Polygon{}), "POLYGON EMPTY");
}

// Ring 1 touches itself at q = (2, 2), where ring 0 (a square) has a corner: two lobes, both
// counter-clockwise, meet at q. The one-sweep acceptance sees ring 0's two edges at q (ring
// neighbours, fine) before ring 1's four; validate() then reports ring 1 alone, at q, with two
// of its edges through q that are not ring neighbours (edges 0, 2, 3 and 5 contain q).
TEST(Validate, RingTouchingItselfAtAnotherRingsCorner) {
  const Point64 q{2, 2};
  const PolygonSet set{{{0, 0}, {2, 0}, q, {0, 2}}, {q, {4, 0}, {5, 1}, q, {5, 3}, {4, 4}}};
  const ValidationReport report = validate(set);
  ASSERT_EQ(report.violations.size(), 1u);
  const Violation& v = report.violations[0];
  EXPECT_EQ(v.rule, Rule::kSelfIntersection);
  EXPECT_EQ(v.polygon, 1u);
  EXPECT_EQ(v.where, q);
  const auto through_q = [](std::size_t e) { return e == 0 || e == 2 || e == 3 || e == 5; };
  EXPECT_TRUE(through_q(v.edge)) << v.describe();
  EXPECT_TRUE(through_q(v.other_edge)) << v.describe();
  EXPECT_LT(v.edge, v.other_edge);
  EXPECT_NE(v.other_edge - v.edge, 1u);  // not ring neighbours (0 and 5 are neighbours too)
  EXPECT_FALSE(v.edge == 0 && v.other_edge == 5);
  // Each lobe alone is a valid triangle: the fault is only the shared point.
  EXPECT_TRUE(validate(Polygon{q, {4, 0}, {5, 1}}).ok());
  EXPECT_TRUE(validate(Polygon{q, {5, 3}, {4, 4}}).ok());
}

// checked.hpp: in the checked build an overflow aborts with a message naming the operation.
// (Coverage cannot count overflow_trap's lines: the aborting child writes no counts.)
TEST(CheckedArithmeticDeathTest, OverflowAbortsNamingTheOperation) {
  if (!arith::kChecked) GTEST_SKIP() << "arithmetic is checked only with EDGELAND_CHECKED";
  volatile std::int64_t largest = std::numeric_limits<std::int64_t>::max();
  EXPECT_DEATH(static_cast<void>(arith::add<std::int64_t>(largest, 1)),
               "integer overflow in checked add");
  EXPECT_DEATH(static_cast<void>(arith::sub<std::int64_t>(-largest, 2)),
               "integer overflow in checked sub");
  EXPECT_DEATH(static_cast<void>(arith::mul<std::int64_t>(largest, 2)),
               "integer overflow in checked mul");
}

}  // namespace
}  // namespace edgeland
