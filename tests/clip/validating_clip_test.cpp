// The validating clip() (PolygonSet operands) checks its operands while it clips them
// (clip/README.md, "Validating while clipping"): cheap per-ring rules first, then noding for
// rings that meet themselves, labeling for faces one operand covers twice, and validate() in
// full wherever those cannot decide. What must hold, whatever the operands: clip() throws
// InvalidInput exactly when validate() rejects an operand, naming the subject first and
// carrying validate()'s own first violation; and when both are valid, it returns exactly what
// the ValidSet overload returns.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <optional>
#include <string>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "support/rc_grid_draws.hpp"
#include "validate_generators.hpp"

namespace edgeland {
namespace {

using testing::grid_point;
using testing::grid_triangle;
using testing::RcDraw;

// An operand that is often invalid in one of the ways only the pipeline's checks see: rings
// touching or crossing themselves, members overlapping, nested, sharing edges in one
// direction; and valid sets dense with contacts (shared edges, vertices on edges).
PolygonSet any_operand() {
  RcDraw draw;
  PolygonSet set;
  switch (draw(0, 6)) {
    case 0: {  // one random ring on a tiny grid: every per-ring rule
      Polygon ring;
      const auto n = draw(3, 10);
      const std::int64_t size = *rc::gen::element<std::int64_t>(2, 3, 4, 6);
      for (std::int64_t k = 0; k < n; ++k) ring.push_back(grid_point(size));
      set.push_back(ring);
      break;
    }
    case 1: {  // triangles on a 4x4 grid: touching, sharing edges, nested, crossing
      const auto count = draw(1, 5);
      for (std::int64_t k = 0; k < count; ++k) set.push_back(grid_triangle(4));
      break;
    }
    case 2: {  // a tiling, valid or with one vertex moved
      set = testing::random_grid_set(draw, static_cast<int>(draw(1, 5)),
                                     *rc::gen::element<std::int64_t>(2, 4), Point64{0, 0});
      if (draw(0, 2) == 0 && !set.empty()) {
        Polygon& p = set[static_cast<std::size_t>(draw(0, static_cast<std::int64_t>(set.size())))];
        p[static_cast<std::size_t>(draw(0, static_cast<std::int64_t>(p.size())))] = grid_point(12);
      }
      break;
    }
    case 3: {  // stars: apart, nested, overlapping, crossing at non-integer points
      const auto count = draw(1, 4);
      for (std::int64_t k = 0; k < count; ++k) {
        Ring star = testing::random_star(draw, grid_point(40), draw(1, 25),
                                         static_cast<std::size_t>(draw(4, 16)));
        if (!star.empty()) set.push_back(star);
      }
      break;
    }
    case 4: {  // a valid member and a copy of it moved by at most one unit, or not at all
      Ring star = testing::random_star(draw, grid_point(30), draw(2, 20),
                                       static_cast<std::size_t>(draw(4, 12)));
      if (star.empty()) break;
      const Point64 d{draw(-1, 2), draw(-1, 2)};
      Ring moved = star;
      for (Point64& p : moved) p = {p.x + d.x, p.y + d.y};
      set = {star, moved};
      break;
    }
    default: {  // a pinched ring: two squares meeting at one vertex, walked as one ring
      const std::int64_t s = draw(1, 6);
      const Point64 o = grid_point(10);
      set.push_back({o,
                     {o.x + s, o.y},
                     {o.x + s, o.y + s},
                     {o.x + 2 * s, o.y + s},
                     {o.x + 2 * s, o.y + 2 * s},
                     {o.x + s, o.y + 2 * s},
                     {o.x + s, o.y + s},
                     {o.x, o.y + s}});
      break;
    }
  }
  // Scaled sometimes, so that crossings with the other operand land on and off the grid.
  const std::int64_t scale = *rc::gen::element<std::int64_t>(1, 1, 3);
  for (Ring& r : set)
    for (Point64& p : r) p = {p.x * scale, p.y * scale};
  return set;
}

std::optional<Violation> first_violation(const PolygonSet& set) {
  const ValidationReport report = validate(set, 1);
  if (report.ok()) return std::nullopt;
  return report.violations.front();
}

void check_agrees(ClipOp op, const PolygonSet& a, const PolygonSet& b) {
  const auto va = first_violation(a), vb = first_violation(b);
  try {
    const ClipResult r = clip(op, a, b, ClipOptions{.checked = true});
    RC_ASSERT(!va.has_value());
    RC_ASSERT(!vb.has_value());
    const ValidClipResult v = clip(op, ValidSet(a), ValidSet(b, Operand::kClip));
    RC_ASSERT(r.polygons == v.set.polygons());
    RC_ASSERT(r.stats.intersections == v.stats.intersections);
    RC_ASSERT(r.stats.vertices_snapped == v.stats.vertices_snapped);
  } catch (const InvalidInput& e) {
    RC_ASSERT(va.has_value() || vb.has_value());
    RC_ASSERT(e.operand == (va ? Operand::kSubject : Operand::kClip));
    RC_ASSERT(e.violation.describe() == (va ? *va : *vb).describe());
  }
}

ClipOp any_op() {
  return *rc::gen::element(ClipOp::kUnion, ClipOp::kIntersection, ClipOp::kDifference,
                           ClipOp::kXor);
}

RC_GTEST_PROP(ValidatingClip, RejectsExactlyWhatValidateRejects, ()) {
  const PolygonSet a = any_operand(), b = any_operand();
  RC_TAG(first_violation(a) || first_violation(b) ? "invalid" : "valid");
  check_agrees(any_op(), a, b);
}

RC_GTEST_PROP(ValidatingClip, RejectsAnInvalidOperandWhateverTheOtherIs, ()) {
  // One operand from the generator above, the other a valid star crossing it off the grid
  // (snap rounding moves something: the coverage check gives way to full validation).
  RcDraw draw;
  const PolygonSet a = any_operand();
  const Ring star = testing::random_star(draw, grid_point(40), draw(3, 30),
                                         static_cast<std::size_t>(draw(4, 16)));
  RC_PRE(!star.empty());
  const PolygonSet b{star};
  if (draw(0, 2) == 0)
    check_agrees(any_op(), a, b);
  else
    check_agrees(any_op(), b, a);
}

// Each way in, named: the check that must see it is in the comment.
void expect_rejected(const PolygonSet& subject, const PolygonSet& clip_set, Operand which,
                     Rule rule) {
  try {
    const ClipResult r = clip(ClipOp::kUnion, subject, clip_set);
    FAIL() << "accepted; result " << to_wkt(r.polygons);
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.operand, which);
    EXPECT_EQ(e.violation.rule, rule) << e.what();
    const auto expected = first_violation(which == Operand::kSubject ? subject : clip_set);
    ASSERT_TRUE(expected.has_value());
    EXPECT_EQ(e.violation.describe(), expected->describe());
  }
}

// Far from everything below (members whose boxes miss it are left out of the pipeline and
// validated in full), and around all of it, touching nothing (every member takes part).
const Polygon kFar{{1000, 1000}, {1010, 1000}, {1005, 1010}};
Polygon square(std::int64_t x, std::int64_t y, std::int64_t s) {
  return {{x, y}, {x + s, y}, {x + s, y + s}, {x, y + s}};
}
const Polygon kAround = square(-100, -100, 300);

TEST(ValidatingClip, ARingTouchingItselfIsSeenByNoding) {
  // Passes every per-ring rule; only noding sees the pinch at (2 2).
  const PolygonSet pinched{{{0, 0}, {2, 0}, {2, 2}, {4, 2}, {4, 4}, {2, 4}, {2, 2}, {0, 2}}};
  expect_rejected(pinched, {kAround}, Operand::kSubject, Rule::kSelfIntersection);
  expect_rejected({kAround}, pinched, Operand::kClip, Rule::kSelfIntersection);
  // A bow tie crossing at a non-integer point.
  expect_rejected({{{0, 0}, {3, 2}, {3, 0}, {0, 1}}}, {kAround}, Operand::kSubject,
                  Rule::kSelfIntersection);
}

TEST(ValidatingClip, MembersCrossingOrOverlappingAlikeAreSeenByNoding) {
  // Noding stops at the first such contact: members crossing properly, members sharing an
  // edge in the same direction (both insides on one side of it).
  expect_rejected({square(0, 0, 4), {{2, 2}, {6, 3}, {6, 6}}}, {kAround}, Operand::kSubject,
                  Rule::kOverlappingInteriors);
  expect_rejected({kAround}, {square(0, 0, 4), {{0, 0}, {4, 0}, {2, 3}}}, Operand::kClip,
                  Rule::kOverlappingInteriors);
  // Many copies of one square: rejected at the first pair, not after all n^2 / 2 of them.
  PolygonSet copies(2000, square(0, 0, 10));
  expect_rejected(copies, {square(5, 5, 10)}, Operand::kSubject, Rule::kOverlappingInteriors);
}

TEST(ValidatingClip, MembersCoveringOneFaceTwiceAreSeenByLabeling) {
  // No contact proves it, and nothing snaps (the other operand touches nothing, or crosses on
  // the grid): labeling's check. A member inside another, apart or touching its edge.
  const PolygonSet nested{square(0, 0, 10), square(2, 2, 3)};
  expect_rejected(nested, {kAround}, Operand::kSubject, Rule::kOverlappingInteriors);
  expect_rejected(nested, {square(4, 4, 10)}, Operand::kSubject, Rule::kOverlappingInteriors);
  expect_rejected({kAround}, {square(0, 0, 10), {{0, 5}, {3, 4}, {3, 6}}}, Operand::kClip,
                  Rule::kOverlappingInteriors);
}

TEST(ValidatingClip, OverlapsAreFoundWhenSnapRoundingMovedSomething) {
  // The other operand crosses off the grid: operands of several members are validated in full.
  const PolygonSet nested{square(0, 0, 10), square(2, 2, 3)};
  expect_rejected(nested, {{{-1, 1}, {12, 2}, {5, 7}}}, Operand::kSubject,
                  Rule::kOverlappingInteriors);
  expect_rejected({kAround}, {square(0, 0, 12), {{0, 5}, {3, 4}, {3, 6}}}, Operand::kClip,
                  Rule::kOverlappingInteriors);
  expect_rejected({{{-1, 1}, {30, 2}, {5, 20}}}, {square(0, 0, 12), {{0, 5}, {3, 4}, {3, 6}}},
                  Operand::kClip, Rule::kOverlappingInteriors);
}

TEST(ValidatingClip, SnapRoundingCanHideAnOverlapFromLabeling) {
  // The clip crosses the small member off the grid and snap rounding folds it flat: in the
  // snapped arrangement nothing is covered twice, so labeling's check would pass. Found by a
  // random search with the full validation of snapped multi-member operands switched off.
  const PolygonSet subject{square(-10, -10, 30), {{3, 1}, {1, 0}, {2, 0}}};
  expect_rejected(subject, {{{-3, 6}, {2, -3}, {1, 7}}}, Operand::kSubject,
                  Rule::kOverlappingInteriors);
}

TEST(ValidatingClip, MembersLeftOutOfThePipelineAreValidatedAnyway) {
  // The overlapping pair is far from the clip operand: the pipeline never sees it.
  const PolygonSet subject{square(0, 0, 4), square(100, 100, 10), square(105, 105, 10)};
  expect_rejected(subject, {square(1, 1, 2)}, Operand::kSubject, Rule::kOverlappingInteriors);
}

TEST(ValidatingClip, TheSubjectIsNamedFirst) {
  const PolygonSet nested{square(0, 0, 10), square(2, 2, 3)};
  const PolygonSet pinched{{{0, 0}, {2, 0}, {2, 2}, {4, 2}, {4, 4}, {2, 4}, {2, 2}, {0, 2}}};
  expect_rejected(nested, pinched, Operand::kSubject, Rule::kOverlappingInteriors);
  expect_rejected(pinched, nested, Operand::kSubject, Rule::kSelfIntersection);
  expect_rejected({kAround}, nested, Operand::kClip, Rule::kOverlappingInteriors);
}

TEST(ValidatingClip, ValidSetsWithManyContactsAreAccepted) {
  // Members sharing edges in opposite directions and meeting at vertices: nothing to reject.
  const PolygonSet tiles{square(0, 0, 2), square(2, 0, 2),          square(0, 2, 2),
                         square(2, 2, 2), {{4, 0}, {6, 0}, {4, 2}}, square(6, 2, 2)};
  const ClipResult r = clip(ClipOp::kUnion, tiles, {square(1, 1, 2)}, ClipOptions{.checked = true});
  EXPECT_EQ(r.polygons,
            clip(ClipOp::kUnion, ValidSet(tiles), ValidSet({square(1, 1, 2)})).set.polygons());
}

}  // namespace
}  // namespace edgeland
