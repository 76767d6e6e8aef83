// join (valid_set.hpp): parts in boxes with disjoint interiors are put together without
// validating again, anything else is validated. What must hold: the result is the parts'
// members in order; it is valid whenever it is returned; and a set that is not valid is refused
// whatever the boxes claim (a member outside its box, boxes that overlap).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/shapes.hpp"
#include "edgeland/kernel/validate.hpp"

namespace edgeland::test {
namespace {

PolygonSet members_of(std::span<const BoxedSet> parts) {
  PolygonSet all;
  for (const BoxedSet& p : parts)
    if (p.set != nullptr) all.insert(all.end(), p.set->polygons().begin(), p.set->polygons().end());
  return all;
}

// A world of 4 x 4 cells, each holding the pieces of one set of circles cut to it: the result is
// the pieces in order, valid, and (cut back up) the circles' area.
TEST(Join, CellsOfOneSetAreThatSetCutUp) {
  PolygonSet circles;  // apart (centres 29 apart), most of them across cell lines
  for (int i = 0; i < 6; ++i) circles.push_back(circle({20 + 25 * i, 30 + 15 * i}, 12));
  const ValidSet whole(circles);
  std::vector<ValidSet> cells;
  std::vector<BoxedSet> parts;
  for (std::int64_t x = 0; x < 4; ++x)
    for (std::int64_t y = 0; y < 4; ++y) {
      const Box64 box{{40 * x, 40 * y}, {40 * x + 40, 40 * y + 40}};
      cells.push_back(clip_to_box(whole, box).set);
      parts.push_back({nullptr, box});
    }
  for (std::size_t i = 0; i < cells.size(); ++i) parts[i].set = &cells[i];
  const ValidSet joined = join(parts);
  EXPECT_EQ(joined.polygons(), members_of(parts));
  EXPECT_TRUE(validate(joined.polygons()).ok());
  EXPECT_GT(joined.polygons().size(), circles.size());
  EXPECT_EQ(twice_signed_area(joined.polygons()), twice_signed_area(circles));
}

TEST(Join, AMemberOutsideItsBoxIsValidatedAndRefused) {
  // Each box holds its part's other member; the overlapping squares cross the line between them.
  const ValidSet left(PolygonSet{box_shape({{0, 0}, {5, 5}}), box_shape({{5, 0}, {15, 5}})});
  const ValidSet right(PolygonSet{box_shape({{12, 0}, {18, 5}})});
  const std::vector<BoxedSet> parts{{&left, {{0, 0}, {10, 10}}}, {&right, {{10, 0}, {20, 10}}}};
  EXPECT_THROW(join(parts), InvalidInput);
}

TEST(Join, OverlappingBoxesAreValidated) {
  const ValidSet a(PolygonSet{box_shape({{0, 0}, {4, 4}})});
  const ValidSet b(PolygonSet{box_shape({{6, 6}, {9, 9}})});
  const ValidSet c(PolygonSet{box_shape({{2, 2}, {7, 7}})});
  const Box64 big{{0, 0}, {10, 10}};
  const std::vector<BoxedSet> apart{{&a, big}, {&b, big}};  // overlapping boxes, members apart
  EXPECT_EQ(join(apart).polygons(), members_of(apart));
  const std::vector<BoxedSet> overlapping{{&a, big}, {&c, big}};
  EXPECT_THROW(join(overlapping), InvalidInput);
}

TEST(Join, BoxesSharingSidesAndNullPartsAreFine) {
  const ValidSet a(PolygonSet{box_shape({{0, 0}, {10, 10}})});
  const ValidSet b(PolygonSet{box_shape({{10, 0}, {20, 10}})});
  const ValidSet c(PolygonSet{box_shape({{0, 10}, {20, 20}})});
  const std::vector<BoxedSet> parts{{&a, {{0, 0}, {10, 10}}},
                                    {nullptr, {{0, 0}, {20, 20}}},
                                    {&b, {{10, 0}, {20, 10}}},
                                    {&c, {{0, 10}, {20, 20}}}};
  EXPECT_EQ(join(parts).polygons(), members_of(parts));
}

// Each part is its box as a square, so the boxes' interiors meet exactly when the members
// overlap: join must refuse exactly those, whatever the sweep over the boxes decides.
RC_GTEST_PROP(JoinProperty, RefusesExactlyTheOverlappingSquares, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(1, 12);
  std::vector<Box64> boxes;
  for (std::size_t i = 0; i < n; ++i) {
    const auto x = *rc::gen::inRange<std::int64_t>(0, 12);
    const auto y = *rc::gen::inRange<std::int64_t>(0, 12);
    const auto w = *rc::gen::inRange<std::int64_t>(1, 6);
    const auto h = *rc::gen::inRange<std::int64_t>(1, 6);
    boxes.push_back({{x, y}, {x + w, y + h}});
  }
  bool overlap = false;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      overlap =
          overlap ||
          (std::min(boxes[i].max.x, boxes[j].max.x) > std::max(boxes[i].min.x, boxes[j].min.x) &&
           std::min(boxes[i].max.y, boxes[j].max.y) > std::max(boxes[i].min.y, boxes[j].min.y));
  std::vector<ValidSet> sets;
  for (const Box64& b : boxes) sets.emplace_back(PolygonSet{box_shape(b)});
  std::vector<BoxedSet> parts;
  for (std::size_t i = 0; i < n; ++i) parts.push_back({&sets[i], boxes[i]});
  if (overlap) {
    RC_ASSERT_THROWS_AS(join(parts), InvalidInput);
  } else {
    RC_ASSERT(join(parts).polygons() == members_of(parts));
  }
}

}  // namespace
}  // namespace edgeland::test
