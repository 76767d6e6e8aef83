// ValidSet (clip.hpp): a set validated once, then carried from operation to operation without
// re-validation. What must hold: it cannot be built from an invalid set; the ValidSet overloads
// return exactly what the PolygonSet overloads return; and a long carving chain on ValidSets
// stays valid at every step (checked mode re-validates each output, and so does the test).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <random>

#include "checked_clip.hpp"
#include "edgeland/kernel/area.hpp"
#include "generators.hpp"
#include "polygon_set_helpers.hpp"

namespace edgeland::test {
namespace {

TEST(ValidSet, RefusesAnInvalidSetNamingTheOperand) {
  // A bow tie: self-intersecting.
  const PolygonSet bow_tie{{{0, 0}, {10, 10}, {10, 0}, {0, 10}}};
  try {
    ValidSet s(bow_tie, Operand::kClip);
    FAIL() << "accepted " << to_wkt(s.polygons());
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.operand, Operand::kClip);
    EXPECT_EQ(e.violation.rule, Rule::kSelfIntersection);
  }
  // Two overlapping squares.
  const PolygonSet overlapping{{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                               {{5, 5}, {15, 5}, {15, 15}, {5, 15}}};
  EXPECT_THROW(ValidSet{overlapping}, InvalidInput);
}

// Issue 16: a coordinate beyond the bound is one typed error wherever it comes in, a
// CoordinateOutOfRange (which is an InvalidInput) naming the operand, polygon and vertex.
TEST(ValidSet, ACoordinateOutOfRangeIsItsOwnError) {
  const std::int64_t far = std::int64_t{1} << 40;
  const PolygonSet shapes{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{20, 0}, {30, 0}, {far, 9}}};
  try {
    ValidSet s(shapes, Operand::kClip);
    FAIL() << "accepted " << to_wkt(s.polygons());
  } catch (const CoordinateOutOfRange& e) {
    EXPECT_EQ(e.operand, Operand::kClip);
    EXPECT_EQ(e.violation.rule, Rule::kCoordinateOutOfRange);
    EXPECT_EQ(e.polygon, 1u);
    EXPECT_EQ(e.vertex, 2u);
    EXPECT_EQ(e.where, (Point64{far, 9}));
  }
  const PolygonSet square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  EXPECT_THROW(clip(ClipOp::kUnion, square, shapes), CoordinateOutOfRange);
  EXPECT_THROW(clip(ClipOp::kUnion, shapes, square), CoordinateOutOfRange);
  // Any other broken rule stays a plain InvalidInput.
  const PolygonSet bow_tie{{{0, 0}, {10, 10}, {10, 0}, {0, 10}}};
  try {
    clip(ClipOp::kUnion, square, bow_tie);
    FAIL() << "accepted a bow tie";
  } catch (const CoordinateOutOfRange&) {
    FAIL() << "a bow tie reported as a coordinate out of range";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.violation.rule, Rule::kSelfIntersection);
  }
}

// merge(): the region as maximal polygons. Two squares sharing an edge are one rectangle;
// a frame of four bars around a hole is split along a diagonal as every output is; the area,
// validity and region are kept.
TEST(Merge, JoinsMembersThatShareEdges) {
  const ValidSet halves(
      PolygonSet{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{10, 0}, {20, 0}, {20, 10}, {10, 10}}});
  const PolygonSet merged = merge(halves).set.polygons();
  EXPECT_EQ(merged, (PolygonSet{{{0, 0}, {20, 0}, {20, 10}, {0, 10}}}));
}

TEST(Merge, AFrameAroundAHoleBecomesHoleFreePieces) {
  const ValidSet frame(PolygonSet{{{0, 0}, {30, 0}, {30, 10}, {0, 10}},
                                  {{0, 20}, {30, 20}, {30, 30}, {0, 30}},
                                  {{0, 10}, {10, 10}, {10, 20}, {0, 20}},
                                  {{20, 10}, {30, 10}, {30, 20}, {20, 20}}});
  const PolygonSet merged = merge(frame).set.polygons();
  EXPECT_TRUE(validate(merged).ok());
  EXPECT_EQ(twice_signed_area(merged), twice_signed_area(frame.polygons()));
  // The hole cannot be one polygon's: at least two pieces, fewer than the four bars' corners.
  EXPECT_GE(merged.size(), 2u);
  std::size_t vertices = 0;
  for (const Polygon& p : merged) vertices += p.size();
  EXPECT_LT(vertices, 16u);
}

// On random valid sets: valid, same area, same region (the xor with the input is empty), and
// merging again changes nothing.
RC_GTEST_PROP(MergeProperty, KeepsTheRegionAndIsIdempotent, ()) {
  const PolygonSet input = *gen::polygon_set({0, 0}, 1000);
  const ValidSet set(input);
  const PolygonSet merged = merge(set).set.polygons();
  RC_ASSERT(validate(merged).ok());
  RC_ASSERT(twice_signed_area(merged) == twice_signed_area(input));
  RC_ASSERT(clip(ClipOp::kXor, input, merged).polygons.empty());
  RC_ASSERT(merge(merge(set).set).set.polygons() == merged);
}

TEST(ValidSet, KeepsTheSetItWasGiven) {
  const PolygonSet s{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{20, 0}, {30, 0}, {25, 9}}};
  EXPECT_EQ(ValidSet(s).polygons(), s);
  EXPECT_TRUE(ValidSet().polygons().empty());
  EXPECT_EQ(ValidSet(s).release(), s);
}

RC_GTEST_PROP(ValidSetProperty, OverloadsGiveIdenticalResults, ()) {
  const OperandPair p = *gen::operand_pair();
  const ClipOp op =
      *rc::gen::element(ClipOp::kUnion, ClipOp::kIntersection, ClipOp::kDifference, ClipOp::kXor);
  const ClipResult plain = clip(op, p.a, p.b, ClipOptions{.checked = true});
  const ValidClipResult valid =
      clip(op, ValidSet(p.a), ValidSet(p.b, Operand::kClip), ClipOptions{.checked = true});
  RC_ASSERT(valid.set.polygons() == plain.polygons);
  RC_ASSERT(valid.stats.intersections == plain.stats.intersections);
  RC_ASSERT(valid.stats.vertices_snapped == plain.stats.vertices_snapped);

  const Box64 box{{-50, -40}, {60, 45}};
  const ClipResult cut = clip_to_box(p.a, box, ClipOptions{.checked = true});
  RC_ASSERT(clip_to_box(ValidSet(p.a), box, ClipOptions{.checked = true}).set.polygons() ==
            cut.polygons);
}

// ValidSets without collinear consecutive vertices (every earlier result; validated sets found
// so, as in OverloadsGiveIdenticalResults above) take the pipeline's shortcut: assembly tests
// only graph vertices for collinearity. The result must be exactly what the same polygons give
// through the PolygonSet overload, which tests every vertex.
RC_GTEST_PROP(ValidSetProperty, CanonicalOperandsGiveIdenticalResults, ()) {
  const OperandPair p = *gen::operand_pair();
  const ClipOp op =
      *rc::gen::element(ClipOp::kUnion, ClipOp::kIntersection, ClipOp::kDifference, ClipOp::kXor);
  // Union with the empty set gives the canonical form of a set, marked as such.
  const ValidSet a = clip(ClipOp::kUnion, ValidSet(p.a), ValidSet()).set;
  const ValidSet b = clip(ClipOp::kUnion, ValidSet(p.b, Operand::kClip), ValidSet()).set;
  const ClipResult plain = clip(op, a.polygons(), b.polygons(), ClipOptions{.checked = true});
  RC_ASSERT(clip(op, a, b, ClipOptions{.checked = true}).set.polygons() == plain.polygons);
  const Box64 box{{-50, -40}, {60, 45}};
  RC_ASSERT(clip_to_box(a, box, ClipOptions{.checked = true}).set.polygons() ==
            clip_to_box(a.polygons(), box, ClipOptions{.checked = true}).polygons);
}

// clip.hpp, clip_to_box: a box corner beyond the bound is a CoordinateOutOfRange naming that
// corner (checked first, even when the box is inverted too), in both overloads.
TEST(ClipToBox, ABoxCornerOutsideTheRangeIsCoordinateOutOfRange) {
  const PolygonSet square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  const ValidSet s(square);
  const Point64 far{kCoordBound + 1, 5};
  for (const Box64& box : {Box64{{0, 0}, far}, Box64{far, {0, 0}}}) {
    try {
      clip_to_box(s, box);
      FAIL() << "accepted a box reaching x = " << far.x;
    } catch (const CoordinateOutOfRange& e) {
      EXPECT_EQ(e.operand, Operand::kClip);
      EXPECT_EQ(e.where, far);
      EXPECT_EQ(e.polygon, 0u);
      EXPECT_EQ(e.ring, 0u);
      EXPECT_EQ(e.vertex, kNone);
    }
    EXPECT_THROW(clip_to_box(square, box), CoordinateOutOfRange);
  }
}

// clip.hpp, clip_to_box: a box with min > max (corners in range) is an InvalidBox, an
// InvalidInput of rule inverted-box that keeps the box; it used to be reported as a coordinate
// out of range at an in-range corner. A box of zero width is no error: its part is empty.
TEST(ClipToBox, AnInvertedBoxIsInvalidBox) {
  const PolygonSet square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  const ValidSet s(square);
  for (const Box64& box : {Box64{{5, 0}, {0, 5}}, Box64{{0, 5}, {5, 0}}}) {
    try {
      clip_to_box(s, box);
      FAIL() << "accepted an inverted box";
    } catch (const CoordinateOutOfRange&) {
      FAIL() << "an inverted box reported as a coordinate out of range";
    } catch (const InvalidBox& e) {
      EXPECT_EQ(e.box, box);
      EXPECT_EQ(e.operand, Operand::kClip);
      EXPECT_EQ(e.violation.rule, Rule::kInvertedBox);
    }
    try {
      clip_to_box(square, box);
      FAIL() << "accepted an inverted box";
    } catch (const InvalidBox& e) {
      EXPECT_EQ(e.box, box);
    }
  }
  EXPECT_THROW(clip_to_box(s, Box64{{5, 0}, {0, 5}}), InvalidInput);  // caught with the rest
  EXPECT_TRUE(clip_to_box(s, Box64{{5, 0}, {5, 5}}).set.polygons().empty());
  EXPECT_TRUE(clip_to_box(square, Box64{{0, 5}, {5, 5}}).polygons.empty());
}

// The carving use: a square carved (and now and then refilled) by 300 random small polygons,
// some overlapping earlier cuts, some crossing its border, each result the next subject, never
// re-validated by the library. Every step must be valid and equal to the PolygonSet chain's.
TEST(ValidSet, CarvingChainStaysValidWithoutRevalidation) {
  std::mt19937_64 rng(7);
  auto uniform = [&](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  };
  ValidSet world(PolygonSet{{{0, 0}, {400, 0}, {400, 400}, {0, 400}}});
  PolygonSet plain_world = world.polygons();
  for (int step = 0; step < 300; ++step) {
    const std::int64_t cx = uniform(-10, 410), cy = uniform(-10, 410), r = uniform(2, 25);
    // A hexagon, convex and counter-clockwise: valid by construction.
    const Polygon tool{{cx - r, cy}, {cx - r / 2, cy - r}, {cx + r / 2, cy - r},
                       {cx + r, cy}, {cx + r / 2, cy + r}, {cx - r / 2, cy + r}};
    const ClipOp op = step % 7 == 6 ? ClipOp::kUnion : ClipOp::kDifference;
    ValidClipResult out =
        clip(op, world, ValidSet(PolygonSet{tool}, Operand::kClip), ClipOptions{.checked = true});
    ASSERT_TRUE(validate(out.set.polygons()).ok()) << "step " << step;
    plain_world = clip(op, plain_world, PolygonSet{tool}).polygons;
    ASSERT_EQ(out.set.polygons(), plain_world) << "step " << step;
    world = std::move(out.set);
  }
  EXPECT_GT(world.polygons().size(), 1u);  // the chain did carve
}

}  // namespace
}  // namespace edgeland::test
