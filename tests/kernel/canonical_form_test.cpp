// canonical_form.hpp: the canonical order of polygon sets, checked from its definition.
#include "edgeland/kernel/canonical_form.hpp"

#include <gtest/gtest.h>

namespace edgeland {
namespace {

const Polygon kSquare{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
const Polygon kRightSquare{{3, 0}, {5, 0}, {5, 2}, {3, 2}};

TEST(CanonicalForm, SortedRingsFromTheirSmallestVertexAreCanonical) {
  EXPECT_TRUE(is_canonical({}));
  EXPECT_TRUE(is_canonical({kSquare}));
  EXPECT_TRUE(is_canonical({kSquare, kRightSquare}));
  // Two rings starting at one shared vertex: the order between them is left open.
  EXPECT_TRUE(is_canonical({kSquare, {{0, 0}, {1, -2}, {1, -1}}}));
  EXPECT_TRUE(is_canonical({{{0, 0}, {1, -2}, {1, -1}}, kSquare}));
  // Points compare by x, then y: (0 -2) is smaller than (0 0).
  EXPECT_FALSE(is_canonical({{{0, 0}, {0, -2}, {1, -1}}}));
}

TEST(CanonicalForm, EachRuleIsReportedWithItsRingAndVertex) {
  const auto rotated = canonical_violation({kSquare, {{5, 0}, {5, 2}, {3, 2}, {3, 0}}});
  ASSERT_TRUE(rotated);
  EXPECT_EQ(rotated->rule, CanonicalRule::kNotStartingAtSmallest);
  EXPECT_EQ(rotated->polygon, 1u);
  EXPECT_EQ(rotated->where, (Point64{3, 0}));
  EXPECT_EQ(rotated->describe(), "not-starting-at-smallest-vertex: polygon 1 at (3 0)");

  const auto collinear = canonical_violation({{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}});
  ASSERT_TRUE(collinear);
  EXPECT_EQ(collinear->rule, CanonicalRule::kCollinearVertex);
  EXPECT_EQ(collinear->where, (Point64{1, 0}));
  EXPECT_EQ(collinear->describe(), "collinear-vertex: polygon 0 at (1 0)");

  // The collinear vertex may be the first one, seen across the ring's closing edge.
  const auto wrapped = canonical_violation({{{0, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 1}}});
  ASSERT_TRUE(wrapped);
  EXPECT_EQ(wrapped->rule, CanonicalRule::kCollinearVertex);
  EXPECT_EQ(wrapped->where, (Point64{0, 1}));

  const auto unsorted = canonical_violation({kRightSquare, kSquare});
  ASSERT_TRUE(unsorted);
  EXPECT_EQ(unsorted->rule, CanonicalRule::kNotSorted);
  EXPECT_EQ(unsorted->polygon, 1u);
  EXPECT_EQ(unsorted->where, (Point64{0, 0}));
  EXPECT_EQ(unsorted->describe(), "not-sorted: polygon 1 at (0 0)");

  const auto tiny = canonical_violation({kSquare, {{7, 7}, {8, 8}}});
  ASSERT_TRUE(tiny);
  EXPECT_EQ(tiny->rule, CanonicalRule::kTooFewVertices);
  EXPECT_EQ(tiny->polygon, 1u);
  EXPECT_EQ(tiny->describe(), "too-few-vertices: polygon 1 at (7 7)");
}

}  // namespace
}  // namespace edgeland
