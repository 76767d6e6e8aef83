// Batch overlays (relabel.hpp: relabel_batch, relabel_cell with several steps): the steps are
// applied in order in one arrangement, one step is relabel() bit for bit, a cell's batch overlay
// (quick cases, small overlay, steps past kMaxBatchSteps in further overlays) is relabel_batch()'s,
// and the input is checked. How a batch relates to its steps one by one, against the exact
// history, is the landscape's property (tests/spatial/landscape_property_test.cpp,
// BatchesAreTheExactHistoryAwayFromBoundaries).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "edgeland/clip/relabel.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "generators.hpp"
#include "relabel_cells.hpp"

namespace edgeland {
namespace {

using test::fill_table;

Polygon square(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

std::vector<RegionLabel> replace_table(RegionLabel from, RegionLabel to) {
  std::vector<RegionLabel> t(256);
  for (RegionLabel l = 0; l < 256; ++l) t[l] = l == from ? to : l;
  return t;
}

// The label of the labeled set at p (0 where no polygon holds it; p is inside or outside them).
RegionLabel label_at(const LabeledSet& s, Point64 p) {
  for (std::size_t i = 0; i < s.labels.size(); ++i)
    if (locate(p, s.set.polygons()[i]) == PointLocation::kInside) return s.labels[i];
  return 0;
}

const Box64 kBox{{0, 0}, {64, 64}};

TEST(RelabelBatch, StepsApplyInOrderInOneArrangement) {
  const ValidSet rock(PolygonSet{square(0, 0, 64, 32)});
  const std::vector<RegionLabel> labels{1};
  const ValidSet left(PolygonSet{square(10, 10, 40, 50)}),
      right(PolygonSet{square(30, 20, 60, 60)});
  const std::vector<RegionLabel> carve = fill_table(0), ore = fill_table(2),
                                 ore_to_gold = replace_table(2, 3);
  // Carve the left square, fill the right one with ore, turn the ore into gold.
  const std::vector<RelabelStep> steps{{&left, carve}, {&right, ore}, {&right, ore_to_gold}};
  const LabeledSet out = relabel_batch(rock, labels, steps, kBox).regions;
  EXPECT_EQ(label_at(out, {20, 15}), 0u);  // carved, not refilled
  EXPECT_EQ(label_at(out, {35, 25}), 3u);  // carved, then ore, then gold
  EXPECT_EQ(label_at(out, {50, 50}), 3u);  // air, then ore, then gold
  EXPECT_EQ(label_at(out, {5, 5}), 1u);    // rock no shape reached
  EXPECT_EQ(label_at(out, {20, 45}), 0u);  // air carved
  // The other order: the ore is carved away where the squares meet.
  const std::vector<RelabelStep> reversed{{&right, ore}, {&left, carve}};
  const LabeledSet other = relabel_batch(rock, labels, reversed, kBox).regions;
  EXPECT_EQ(label_at(other, {35, 25}), 0u);
  EXPECT_EQ(label_at(other, {50, 50}), 2u);
}

TEST(RelabelBatch, OneStepIsRelabel) {
  const ValidSet rock(PolygonSet{square(0, 0, 64, 32), square(5, 40, 30, 50)});
  const std::vector<RegionLabel> labels{1, 2};
  const ValidSet shape(PolygonSet{{{3, 10}, {50, 17}, {43, 90}, {11, 71}}});
  const std::vector<RegionLabel> table = fill_table(3);
  const std::vector<RelabelStep> one{{&shape, table}};
  EXPECT_TRUE(same_content(relabel_batch(rock, labels, one, kBox).regions,
                           relabel(rock, labels, shape, kBox, table).regions));
}

TEST(RelabelBatch, RefusesTooManyStepsAndStepsWithoutAShape) {
  const ValidSet rock(PolygonSet{square(0, 0, 64, 32)}), shape(PolygonSet{square(1, 1, 9, 9)});
  const std::vector<RegionLabel> labels{1}, carve = fill_table(0);
  const std::vector<RelabelStep> many(kMaxBatchSteps + 1, RelabelStep{&shape, carve});
  EXPECT_THROW(relabel_batch(rock, labels, many, kBox), InvalidOverlay);
  const std::vector<RelabelStep> none{{&shape, carve}, {nullptr, carve}};
  try {
    relabel_batch(rock, labels, none, kBox);
    FAIL() << "a step without a shape was taken";
  } catch (const InvalidOverlay& e) {
    EXPECT_EQ(e.reason, InvalidOverlay::Reason::kNoShape);
    EXPECT_EQ(e.index, 1u);
  }
  EXPECT_THROW(relabel_cell({rock, labels}, none, kBox), InvalidOverlay);
}

// A cell: the canonical decomposition of a few random fills, as a landscape cell holds.
LabeledSet random_cell(std::int64_t size) { return test::random_cell_content(size); }

std::vector<RegionLabel> random_table() {
  std::vector<RegionLabel> table(256);
  const RegionLabel to = *rc::gen::inRange<RegionLabel>(0, 4);
  const int kind = *rc::gen::inRange(0, 3);
  for (RegionLabel l = 0; l < 256; ++l)
    table[l] = kind == 0 ? to : kind == 1 ? (l == 0 ? to : l) : (l == 1 ? to : l);
  return table;
}

// A cell's batch overlay, with shapes near and over it, is relabel_batch()'s; checked mode
// compares it too.
RC_GTEST_PROP(RelabelBatchProperty, ACellsBatchIsRelabelBatchs, ()) {
  const std::int64_t size = *rc::gen::element<std::int64_t>(16, 64, 256);
  const Box64 box{{0, 0}, {size, size}};
  const LabeledSet cell = random_cell(size);
  const int n = *rc::gen::inRange(2, 5);
  std::vector<ValidSet> shapes;
  std::vector<std::vector<RegionLabel>> tables;
  for (int k = 0; k < n; ++k) {
    const std::int64_t r = *rc::gen::element<std::int64_t>(2, 5, size / 8, size / 4, size);
    shapes.emplace_back(*test::gen::polygon_set(*test::gen::point_in({0, 0}, {size, size}), r));
    tables.push_back(random_table());
  }
  std::vector<RelabelStep> steps;
  for (int k = 0; k < n; ++k) steps.push_back({&shapes[k], tables[k]});
  const CellOverlayResult got = relabel_cell(cell, steps, box, {.checked = true});
  const LabeledSet want = relabel_batch(cell.set, cell.labels, steps, box).regions;
  RC_TAG(static_cast<int>(got.path), got.content ? "changed" : "unchanged");
  RC_ASSERT(same_content(got.content ? *got.content : cell, want));
}

// Past kMaxBatchSteps a cell's batch takes further overlays: relabel_batch() of the first
// kMaxBatchSteps steps, then of the rest on its result.
TEST(RelabelCell, StepsPastOneOverlayTakeTheNext) {
  const LabeledSet cell{ValidSet(PolygonSet{square(0, 0, 64, 40)}), {1}};
  std::vector<ValidSet> shapes;
  for (std::int64_t k = 0; k < 20; ++k)
    shapes.emplace_back(PolygonSet{{{3 * k, 30}, {3 * k + 7, 33}, {3 * k + 2, 50}}});
  const std::vector<RegionLabel> carve = fill_table(0), ore = fill_table(2);
  std::vector<RelabelStep> steps;
  for (std::size_t k = 0; k < shapes.size(); ++k)
    steps.push_back({&shapes[k], k % 2 ? ore : carve});
  const CellOverlayResult got = relabel_cell(cell, steps, kBox, {.checked = true});
  const std::span<const RelabelStep> all(steps);
  const LabeledSet first =
      relabel_batch(cell.set, cell.labels, all.first(kMaxBatchSteps), kBox).regions;
  const LabeledSet then =
      relabel_batch(first.set, first.labels, all.subspan(kMaxBatchSteps), kBox).regions;
  ASSERT_TRUE(got.content.has_value());
  EXPECT_TRUE(same_content(*got.content, then));
}

}  // namespace
}  // namespace edgeland
