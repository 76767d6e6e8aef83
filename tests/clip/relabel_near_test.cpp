// relabel_near() (relabel.hpp): relabel() with the regions the shape cannot reach left out of
// the arrangement. What must hold: on a canonical decomposition (an earlier relabel()'s
// result) it gives relabel()'s result byte for byte, whatever the shape, the table and the
// window; on other input its result is valid, every point labeled as relabel() labels it.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "edgeland/clip/relabel.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "generators.hpp"
#include "polygon_set_helpers.hpp"
#include "shape_builders.hpp"

namespace edgeland::test {
namespace {

const ClipOptions kChecked{.checked = true};

Polygon box_polygon(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A k x k grid of cells of side `size` from the origin, each one of three labels or empty,
// as the canonical decomposition of its regions (pinches, holes and T-junctions occur).
LabeledSet grid_regions(int k, std::int64_t size) {
  PolygonSet cells;
  std::vector<RegionLabel> labels;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const RegionLabel l = *rc::gen::inRange<RegionLabel>(0, 4);
      if (l == 0) continue;
      cells.push_back(box_polygon(i * size, j * size, (i + 1) * size, (j + 1) * size));
      labels.push_back(l);
    }
  const Box64 window{{0, 0}, {k * size, k * size}};
  return relabel(ValidSet(cells), labels, ValidSet(), window, {}, kChecked).regions;
}

// A shape of one to three members around points of the window, each member within r of its
// point (so members may reach past the window: the window's ring takes part then).
ValidSet shape_near(const Box64& window, std::int64_t r) {
  PolygonSet members;
  const int n = *rc::gen::inRange(1, 4);
  for (int i = 0; i < n; ++i)
    members.push_back(*gen::shape(*gen::point_in(window.min, window.max), r));
  return ValidSet(keep_valid(members), Operand::kClip);
}

std::vector<RegionLabel> table_of_up_to(RegionLabel labels) {
  std::vector<RegionLabel> table;
  const int size = *rc::gen::inRange(1, 5);
  for (int i = 0; i < size; ++i) table.push_back(*rc::gen::inRange<RegionLabel>(0, labels));
  return table;
}

// A sequence of small overlays, each on the result of the one before (the way a landscape cell
// is worn), every one compared with relabel().
RC_GTEST_PROP(RelabelNearProperty, IsRelabelOnCanonicalDecompositions, ()) {
  const int k = *rc::gen::inRange(2, 7);
  const std::int64_t size = *rc::gen::element<std::int64_t>(3, 10, 40);
  const Box64 window{{0, 0}, {k * size, k * size}};
  LabeledSet regions = grid_regions(k, size);
  const int overlays = *rc::gen::inRange(1, 7);
  bool left_something_out = false;
  for (int i = 0; i < overlays; ++i) {
    const ValidSet shape = shape_near(window, *rc::gen::inRange<std::int64_t>(1, 2 * size));
    const std::vector<RegionLabel> table = table_of_up_to(4);
    const LabeledClipResult full =
        relabel(regions.set, regions.labels, shape, window, table, kChecked);
    const LabeledClipResult near =
        relabel_near(regions.set, regions.labels, shape, window, table, kChecked);
    RC_LOG() << "regions " << to_wkt(regions.set.polygons()) << "\nshape "
             << to_wkt(shape.polygons()) << "\nlabels";
    for (RegionLabel l : regions.labels) RC_LOG() << ' ' << l;
    RC_LOG() << "\ntable";
    for (RegionLabel l : table) RC_LOG() << ' ' << l;
    RC_LOG() << "\n";
    RC_ASSERT(near.regions.set.polygons() == full.regions.set.polygons());
    RC_ASSERT(near.regions.labels == full.regions.labels);
    left_something_out = left_something_out || near.pieces_left_out > 0;
    regions = full.regions;
  }
  RC_TAG(left_something_out ? "pieces left out" : "every piece in play");
}

// Thin pieces and slivers beside each other: snap rounding moves segments next to pieces the
// filter first leaves out, so it has to bring them in and run again.
RC_GTEST_PROP(RelabelNearProperty, IsRelabelAmongSliversAndMovedSegments, ()) {
  const Box64 window{{-20, -20}, {80, 80}};
  PolygonSet pieces;
  std::vector<RegionLabel> labels;
  const int n = *rc::gen::inRange(2, 13);
  for (int i = 0; i < n; ++i) {
    pieces.push_back(*gen::sliver(*gen::point_in({16, 16}, {44, 44}), 8));
    labels.push_back(*rc::gen::inRange<RegionLabel>(1, 4));
  }
  pieces = keep_valid(pieces);
  labels.resize(pieces.size());
  LabeledSet regions = relabel(ValidSet(pieces), labels, ValidSet(), window, {}, kChecked).regions;
  for (int i = 0; i < 5; ++i) {
    const ValidSet shape(PolygonSet{*gen::sliver(*gen::point_in({16, 16}, {44, 44}), 8)},
                         Operand::kClip);
    const std::vector<RegionLabel> table = table_of_up_to(4);
    const LabeledClipResult full =
        relabel(regions.set, regions.labels, shape, window, table, kChecked);
    const LabeledClipResult near =
        relabel_near(regions.set, regions.labels, shape, window, table, kChecked);
    RC_ASSERT(near.regions.set.polygons() == full.regions.set.polygons());
    RC_ASSERT(near.regions.labels == full.regions.labels);
    regions = full.regions;
  }
}

// relabel_near()'s result, expected to be relabel()'s.
LabeledClipResult near_and_full_agree(const LabeledSet& regions, const ValidSet& shape,
                                      const Box64& window, const std::vector<RegionLabel>& table) {
  LabeledClipResult near =
      relabel_near(regions.set, regions.labels, shape, window, table, kChecked);
  const LabeledClipResult full =
      relabel(regions.set, regions.labels, shape, window, table, kChecked);
  EXPECT_EQ(near.regions.set.polygons(), full.regions.set.polygons());
  EXPECT_EQ(near.regions.labels, full.regions.labels);
  return near;
}

TEST(RelabelNear, KeepsAFarRegionAsItIsAndChangesTheNearOne) {
  // Two rock squares (1) apart and an ore square (2) beside the first; a carve in the first.
  const PolygonSet pieces{box_polygon(0, 0, 10, 10), box_polygon(10, 0, 20, 10),
                          box_polygon(40, 40, 50, 50)};
  const std::vector<RegionLabel> labels{1, 2, 1};
  const Box64 window{{0, 0}, {50, 50}};
  const LabeledSet regions =
      relabel(ValidSet(pieces), labels, ValidSet(), window, {}, kChecked).regions;
  const ValidSet hole(PolygonSet{box_polygon(3, 3, 6, 7)});
  const std::vector<RegionLabel> carve{0, 0, 2};  // rock to air, ore kept
  const LabeledClipResult near = near_and_full_agree(regions, hole, window, carve);
  // Left out: the far square and the ore beside the carved one (a unit or more from the hole).
  EXPECT_EQ(near.pieces_left_out, 2u);
  // The carve left a hole in the first square (cut into pieces), the far square as it was.
  EXPECT_EQ(twice_area(near.regions.set.polygons()), 2 * (300 - 12));
  EXPECT_NE(std::find(near.regions.set.polygons().begin(), near.regions.set.polygons().end(),
                      box_polygon(40, 40, 50, 50)),
            near.regions.set.polygons().end());
}

TEST(RelabelNear, TakesTheWholeRegionWhenTheShapeReachesSomeOfItsPieces) {
  // One region cut by its bridges into three pieces (found by the property above when pieces
  // were left out one by one): a shape near two of them, changing nothing, must bring in the
  // third, or the two would be decomposed as a region of their own.
  const PolygonSet pieces{{{4, 5}, {6, 6}, {9, 6}, {9, 9}, {4, 9}},
                          {{4, 9}, {8, 9}, {9, 10}, {12, 12}, {9, 12}, {9, 11}},
                          {{9, 9}, {12, 9}, {12, 12}, {9, 10}}};
  const Box64 window{{-5, -5}, {15, 15}};
  const LabeledSet regions =
      relabel(ValidSet(pieces), std::vector<RegionLabel>{2, 2, 2}, ValidSet(), window, {}, kChecked)
          .regions;
  ASSERT_EQ(regions.set.polygons(), pieces);  // already its canonical decomposition
  const ValidSet shape(
      PolygonSet{{{-1, 6}, {3, 6}, {1, 7}, {0, 7}, {-2, 8}, {-3, 8}, {-1, 7}, {-3, 7}}});
  const std::vector<RegionLabel> table{0};
  near_and_full_agree(regions, shape, window, table);
}

TEST(RelabelNear, OnOtherInputLabelsEveryPointAsRelabelDoes) {
  // Two rock squares sharing an edge: relabel() merges them; far from the shape, relabel_near()
  // keeps them as given, a valid set covering the same points with the same label.
  const PolygonSet pieces{box_polygon(30, 30, 40, 40), box_polygon(40, 30, 50, 40)};
  const std::vector<RegionLabel> labels{1, 1};
  const ValidSet shape(PolygonSet{box_polygon(0, 0, 5, 5)});
  const std::vector<RegionLabel> fill{1};
  const Box64 window{{0, 0}, {50, 50}};
  const LabeledClipResult near =
      relabel_near(ValidSet(pieces), labels, shape, window, fill, kChecked);
  EXPECT_TRUE(validate(near.regions.set.polygons()).ok());
  EXPECT_EQ(near.regions.labels, (std::vector<RegionLabel>{1, 1, 1}));
  EXPECT_EQ(twice_area(near.regions.set.polygons()), 2 * (25 + 200));
  const LabeledClipResult full = relabel(ValidSet(pieces), labels, shape, window, fill, kChecked);
  EXPECT_EQ(full.regions.labels.size(), 2u);
  EXPECT_EQ(twice_area(full.regions.set.polygons()), 2 * (25 + 200));
}

TEST(RelabelNear, RejectsArgumentsAsRelabelDoes) {
  const ValidSet one(PolygonSet{box_polygon(0, 0, 10, 10)});
  const std::vector<RegionLabel> zero{0};
  EXPECT_THROW(relabel_near(one, zero, ValidSet(), {{0, 0}, {10, 10}}, {}), InvalidOverlay);
  const std::vector<RegionLabel> one_label{1};
  EXPECT_THROW(relabel_near(one, one_label, ValidSet(), {{0, 0}, {5, 5}}, {}), InvalidOverlay);
  EXPECT_THROW(relabel_near(one, {}, ValidSet(), {{0, 0}, {10, 10}}, {}), InvalidOverlay);
}

}  // namespace
}  // namespace edgeland::test
