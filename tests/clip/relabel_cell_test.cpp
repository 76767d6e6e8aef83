// Stage test of a landscape cell's overlay (relabel_cell(), relabel.hpp): each quick case
// (relabel_quick.hpp) fires where it should, and whenever one answers, the answer is relabel()'s,
// bit for bit; every overlay, quick, small or general, is relabel()'s (clip/README.md, "The
// small overlay").
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "edgeland/clip/relabel.hpp"
#include "generators.hpp"
#include "relabel_cells.hpp"
#include "relabel_quick.hpp"
#include "small_overlay.hpp"

namespace edgeland {
namespace {

using test::fill_table;

Polygon square(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

std::vector<RegionLabel> carve_table() { return fill_table(0); }

// A cell: its box and the canonical decomposition of labeled polygons in it.
struct Cell {
  Box64 box;
  LabeledSet content;
};

Cell cell_of(const Box64& box, const PolygonSet& polygons, const std::vector<RegionLabel>& labels) {
  return {box, relabel(ValidSet(polygons), labels, ValidSet(), box, {}).regions};
}

bool same(const LabeledSet& a, const LabeledSet& b) {
  return a.labels == b.labels && a.set.polygons() == b.set.polygons();
}

// What relabel() gives for the cell: nullopt when that is the cell's own content.
std::optional<LabeledSet> by_relabel(const Cell& cell, const ValidSet& shape,
                                     const std::vector<RegionLabel>& table) {
  LabeledClipResult r = relabel(cell.content.set, cell.content.labels, shape, cell.box, table);
  if (same(r.regions, cell.content)) return std::nullopt;
  return std::move(r.regions);
}

// The quick cases' answer for the cell.
std::optional<detail::QuickAnswer> quick(const Cell& cell, const ValidSet& shape,
                                         const std::vector<RegionLabel>& table) {
  std::vector<Box64> boxes;
  for (const Polygon& p : cell.content.set.polygons()) boxes.push_back(*bounding_box(p));
  const detail::ShapeNearWindow near = detail::shape_near_window(shape, cell.box);
  return detail::quick_overlay({cell.content, boxes, cell.box}, shape, near, table);
}

// The quick answer exists, comes from case `which`, and is relabel()'s.
void expect_quick_and_exact(const Cell& cell, const ValidSet& shape,
                            const std::vector<RegionLabel>& table, detail::QuickCase which) {
  const auto answer = quick(cell, shape, table);
  ASSERT_TRUE(answer.has_value());
  EXPECT_EQ(answer->which, which);
  const auto exact = by_relabel(cell, shape, table);
  ASSERT_EQ(answer->content.has_value(), exact.has_value());
  if (exact) {
    EXPECT_TRUE(same(*answer->content, *exact));
  }
}

const Box64 kBox{{0, 0}, {64, 64}};

TEST(RelabelCellQuick, AnEmptyCellCarvedStaysEmpty) {
  const Cell cell = cell_of(kBox, {}, {});
  const ValidSet shape(PolygonSet{square(10, 10, 90, 30)});
  expect_quick_and_exact(cell, shape, carve_table(), detail::QuickCase::kEmptyStaysEmpty);
  EXPECT_FALSE(quick(cell, shape, carve_table())->content.has_value());
}

TEST(RelabelCellQuick, ACoveredCellCarvedBecomesEmpty) {
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 20), square(5, 30, 40, 50)}, {1, 2});
  const ValidSet shape(PolygonSet{square(-10, -10, 70, 80)});
  expect_quick_and_exact(cell, shape, carve_table(), detail::QuickCase::kCoveredUniform);
}

TEST(RelabelCellQuick, ACoveredCellFilledBecomesTheCellBox) {
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 20), square(5, 30, 40, 50)}, {1, 2});
  const ValidSet shape(PolygonSet{{{-20, -100}, {200, 32}, {-20, 200}}});  // a triangle around it
  expect_quick_and_exact(cell, shape, fill_table(3), detail::QuickCase::kCoveredUniform);
  const auto answer = quick(cell, shape, fill_table(3));
  ASSERT_TRUE(answer->content.has_value());
  EXPECT_EQ(answer->content->set.polygons(), PolygonSet{square(0, 0, 64, 64)});
  EXPECT_EQ(answer->content->labels, std::vector<RegionLabel>{3});
}

TEST(RelabelCellQuick, ACoveredCellWhoseMaterialsAllStayIsKept) {
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 20)}, {1});
  const ValidSet shape(PolygonSet{square(-1, -1, 65, 65)});
  std::vector<RegionLabel> replace_2_by_3(256);
  for (RegionLabel l = 0; l < 256; ++l) replace_2_by_3[l] = l == 2 ? 3 : l;
  expect_quick_and_exact(cell, shape, replace_2_by_3, detail::QuickCase::kCoveredUnchanged);
}

TEST(RelabelCellQuick, ACoveredCellOfMixedOutcomeGoesToTheOverlay) {
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 20), square(5, 30, 40, 50)}, {1, 2});
  const ValidSet shape(PolygonSet{square(-1, -1, 65, 65)});
  std::vector<RegionLabel> replace_1_by_2(256);
  for (RegionLabel l = 0; l < 256; ++l) replace_1_by_2[l] = l == 1 ? 2 : l;
  EXPECT_FALSE(quick(cell, shape, replace_1_by_2).has_value());
}

TEST(RelabelCellQuick, ACarveIntoAirChangesNothing) {
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 20)}, {1});
  // Crossing the cell's top line, at least two units above the rock.
  expect_quick_and_exact(cell, ValidSet(PolygonSet{{{10, 23}, {50, 40}, {30, 90}}}), carve_table(),
                         detail::QuickCase::kClearOfTheShape);
}

TEST(RelabelCellQuick, AFillOfRockIntoRockChangesNothing) {
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 40), square(10, 50, 20, 60)}, {1, 2});
  expect_quick_and_exact(cell, ValidSet(PolygonSet{{{10, 10}, {50, 17}, {30, 35}}}), fill_table(1),
                         detail::QuickCase::kThroughKeptRegions);
}

TEST(RelabelCellQuick, AFillOfRockIntoRockAUnitFromAirChangesNothing) {
  // A unit below the rock's top edge: too near for kThroughKeptRegions, but inside the cell box
  // and meeting no edge at all, so nothing is rounded.
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 40), square(10, 50, 20, 60)}, {1, 2});
  expect_quick_and_exact(cell, ValidSet(PolygonSet{{{10, 10}, {50, 17}, {30, 39}}}), fill_table(1),
                         detail::QuickCase::kInsideOneFace);
}

TEST(RelabelCellQuick, AFillAroundAnIslandOfAnotherMaterialGoesToTheOverlay) {
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 40), square(10, 50, 20, 60)}, {1, 2});
  // Inside the cell, meeting no edge, but holding the island of material 2.
  EXPECT_FALSE(quick(cell, ValidSet(PolygonSet{square(5, 45, 30, 62)}), fill_table(1)).has_value());
}

TEST(RelabelCellQuick, AShapeAUnitFromABoundaryGoesToTheOverlay) {
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 20)}, {1});
  // Crossing the cell's top line one unit above the rock: rounding may reach the rock.
  EXPECT_FALSE(
      quick(cell, ValidSet(PolygonSet{{{10, 21}, {50, 40}, {30, 90}}}), carve_table()).has_value());
}

TEST(RelabelCellQuick, AFillOfRockIntoRockOverACellLineChangesNothing) {
  // Rock and ore fill the cell; a fill of rock reaches in over the cell's top line, in the rock,
  // and crosses the line at points that are not integer (rounded onto the line).
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 40), square(0, 40, 64, 64)}, {2, 1});
  const ValidSet shape(PolygonSet{{{10, 50}, {37, 61}, {51, 90}, {3, 77}}});
  expect_quick_and_exact(cell, shape, fill_table(1), detail::QuickCase::kThroughKeptRegions);
}

TEST(RelabelCellQuick, ACarveIntoAirOverACellLineBesideRockChangesNothing) {
  // Rock with a bay of air open to the right side; the carve enters the bay over the side line,
  // two units from the rock (the rock's box holds the whole carve: no polygon is clear of it).
  const Cell cell = cell_of(
      kBox, {{{0, 0}, {64, 0}, {64, 20}, {30, 20}, {30, 44}, {64, 44}, {64, 64}, {0, 64}}}, {1});
  const ValidSet shape(PolygonSet{{{33, 23}, {90, 22}, {80, 41}, {40, 41}}});
  expect_quick_and_exact(cell, shape, carve_table(), detail::QuickCase::kThroughKeptRegions);
}

TEST(RelabelCellQuick, AFillOfRockIntoRockOverACellLineBesideAirChangesNothing) {
  // Rock over the upper part of the cell, air below it; the fill reaches in over the top line
  // and stays in the rock, two units from the air.
  const Cell cell = cell_of(kBox, {square(0, 30, 64, 64)}, {1});
  const ValidSet shape(PolygonSet{{{10, 50}, {37, 61}, {51, 90}, {3, 77}}});
  expect_quick_and_exact(cell, shape, fill_table(1), detail::QuickCase::kThroughKeptRegions);
}

TEST(RelabelCellQuick, AFillOverACellLineAroundAnAirPocketGoesToTheOverlay) {
  // The rock holds a pocket of air inside the fill, away from its edges.
  const Cell cell = cell_of(kBox, {square(0, 30, 64, 64)}, {1});
  const LabeledClipResult pocket =
      relabel(cell.content.set, cell.content.labels, ValidSet(PolygonSet{square(20, 48, 30, 56)}),
              kBox, carve_table());
  const Cell holed{kBox, pocket.regions};
  const ValidSet shape(PolygonSet{{{10, 44}, {40, 44}, {40, 90}, {10, 90}}});
  EXPECT_FALSE(quick(holed, shape, fill_table(1)).has_value());
}

TEST(RelabelCellQuick, AFillOverACellLineIntoAnotherMaterialGoesToTheOverlay) {
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 40), square(0, 40, 64, 64)}, {2, 1});
  // Reaching over the top line into the rock and on into the ore below.
  const ValidSet shape(PolygonSet{{{10, 30}, {37, 35}, {51, 90}, {3, 77}}});
  EXPECT_FALSE(quick(cell, shape, fill_table(1)).has_value());
}

TEST(RelabelCellQuick, AFillOverACellLineAroundAnIslandGoesToTheOverlay) {
  // The ore island lies inside the fill, away from its edges.
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 40), square(20, 50, 30, 56)}, {1, 2});
  const ValidSet shape(PolygonSet{{{10, 44}, {40, 44}, {40, 90}, {10, 90}}});
  EXPECT_FALSE(quick(cell, shape, fill_table(1)).has_value());
}

TEST(RelabelCellQuick, AFillIntoAirBesideRockGoesToTheOverlay) {
  // Everything the fill meets in the cell is air, which it changes.
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 20)}, {1});
  const ValidSet shape(PolygonSet{{{10, 30}, {50, 30}, {50, 90}, {10, 90}}});
  EXPECT_FALSE(quick(cell, shape, fill_table(1)).has_value());
}

TEST(RelabelCellQuick, AnEdgeCrossingTheWholeCellGoesToTheOverlay) {
  // A long edge of the shape crosses the cell with no vertex in it: which region it passes
  // through is not read from a vertex, so the overlay decides.
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 20)}, {1});
  const ValidSet shape(PolygonSet{{{-10, 30}, {100, 40}, {100, 90}, {-10, 90}}});
  EXPECT_FALSE(quick(cell, shape, fill_table(1)).has_value());
}

// The cell overlay of a cell and a shape through it, with its path, against relabel().
void expect_overlay_by(const Cell& cell, const ValidSet& shape,
                       const std::vector<RegionLabel>& table, CellOverlayPath path) {
  const CellOverlayResult r = relabel_cell(cell.content, shape, cell.box, table, {.checked = true});
  EXPECT_EQ(r.path, path);
  const auto exact = by_relabel(cell, shape, table);
  ASSERT_EQ(r.content.has_value(), exact.has_value());
  if (exact) {
    EXPECT_TRUE(same(*r.content, *exact));
  }
}

TEST(RelabelCell, ACellOfTensOfEdgesTakesTheSmallOverlay) {
  const Cell cell = cell_of(kBox, {square(0, 0, 64, 20), square(5, 30, 40, 50)}, {1, 2});
  // Crossing both regions and the cell's top line at points that are not integer.
  const ValidSet shape(PolygonSet{{{3, 10}, {50, 17}, {43, 90}, {11, 71}}});
  expect_overlay_by(cell, shape, carve_table(), CellOverlayPath::kSmall);
  expect_overlay_by(cell, shape, fill_table(3), CellOverlayPath::kSmall);
}

// A cell of more edges than the small overlay takes (a cell at min_cell_size, or in a grid, may
// hold hundreds): the general pipeline answers, and its answer is relabel()'s too.
TEST(RelabelCell, ACellOfHundredsOfEdgesFallsBackToTheGeneralPipeline) {
  PolygonSet squares;
  std::vector<RegionLabel> labels;
  for (std::int64_t i = 0; i < 8; ++i)
    for (std::int64_t j = 0; j < 8; ++j) {
      squares.push_back(square(8 * i, 8 * j, 8 * i + 5, 8 * j + 5));
      labels.push_back(static_cast<RegionLabel>(1 + (i + j) % 2));
    }
  const Cell cell = cell_of(kBox, squares, labels);
  ASSERT_GT(4 * cell.content.labels.size(), detail::kSmallOverlayUpTo - 8);
  const ValidSet shape(PolygonSet{{{-3, 2}, {70, 29}, {31, 80}}});
  expect_overlay_by(cell, shape, carve_table(), CellOverlayPath::kGeneral);
  expect_overlay_by(cell, shape, fill_table(2), CellOverlayPath::kGeneral);
}

// A random cell: up to four fills of random shapes of materials 1-3 into a box of this size.
Cell random_cell(std::int64_t size) {
  return {{{0, 0}, {size, size}}, test::random_cell_content(size)};
}

// A random edit's table: fill (carve when `to` is 0), fill_empty or replace 1.
std::vector<RegionLabel> random_table() {
  std::vector<RegionLabel> table(256);
  const RegionLabel to = *rc::gen::inRange<RegionLabel>(0, 4);
  const int kind = *rc::gen::inRange(0, 3);
  for (RegionLabel l = 0; l < 256; ++l)
    table[l] = kind == 0 ? to : kind == 1 ? (l == 0 ? to : l) : (l == 1 ? to : l);
  return table;
}

// Whenever a quick case answers, the answer is relabel()'s (tagged by case and outcome).
void check_quick_against_relabel(const Cell& cell, const ValidSet& shape,
                                 const std::vector<RegionLabel>& table) {
  const auto answer = quick(cell, shape, table);
  RC_TAG(cell.content.labels.empty() ? "empty cell" : "cell with polygons",
         !answer ? -1 : static_cast<int>(answer->which), answer && answer->content);
  if (!answer) return;
  const auto exact = by_relabel(cell, shape, table);
  RC_ASSERT(answer->content.has_value() == exact.has_value());
  if (exact) RC_ASSERT(same(*answer->content, *exact));
}

// Random cells and a random edit anywhere near the cell.
RC_GTEST_PROP(RelabelCellProperty, EveryQuickAnswerIsTheOverlays, ()) {
  const std::int64_t size = *rc::gen::element<std::int64_t>(16, 64, 256);
  const Cell cell = random_cell(size);
  const std::int64_t r = *rc::gen::element<std::int64_t>(2, 5, size / 4, size, 3 * size);
  const Point64 c =
      *test::gen::point_in({-size / 4, -size / 4}, {size + size / 4, size + size / 4});
  check_quick_against_relabel(cell, ValidSet(*test::gen::polygon_set(c, r)), random_table());
}

// Random cells and a random edit centred near one of the cell's side lines, so that it crosses
// them: where kThroughKeptRegions answers, with snap rounding on the side lines.
RC_GTEST_PROP(RelabelCellProperty, QuickAnswersOverTheSideLinesAreTheOverlays, ()) {
  const std::int64_t size = *rc::gen::element<std::int64_t>(16, 64, 256);
  const Cell cell = random_cell(size);
  const std::int64_t r = *rc::gen::element<std::int64_t>(2, 5, size / 8, size / 4);
  const std::int64_t along = *rc::gen::inRange<std::int64_t>(0, size + 1);
  const std::int64_t off = *rc::gen::inRange<std::int64_t>(-r, r + 1);
  const int side = *rc::gen::inRange(0, 4);
  const Point64 c = side == 0   ? Point64{off, along}
                    : side == 1 ? Point64{size + off, along}
                    : side == 2 ? Point64{along, off}
                                : Point64{along, size + off};
  check_quick_against_relabel(cell, ValidSet(*test::gen::polygon_set(c, r)), random_table());
}

// The whole overlay of a cell (quick cases, then relabel_near()'s arrangement by the small
// overlay, which leaves the regions the shape cannot reach out of it) is relabel()'s, with small
// shapes so that some regions of the cell are out of their reach.
RC_GTEST_PROP(RelabelCellProperty, EveryOverlayIsRelabels, ()) {
  const std::int64_t size = *rc::gen::element<std::int64_t>(16, 64, 256);
  const Cell cell = random_cell(size);
  const std::int64_t r = *rc::gen::element<std::int64_t>(2, 5, size / 8, size / 4, size);
  const Point64 c = *test::gen::point_in({0, 0}, {size, size});
  const ValidSet shape(*test::gen::polygon_set(c, r));
  const std::vector<RegionLabel> table = random_table();
  const CellOverlayResult result =
      relabel_cell(cell.content, shape, cell.box, table, {.checked = true});
  const auto& overlay = result.content;
  const auto exact = by_relabel(cell, shape, table);
  RC_TAG(cell.content.labels.size() > 1 ? "several pieces" : "one piece or none",
         static_cast<int>(result.path));
  RC_ASSERT(overlay.has_value() == exact.has_value());
  if (exact) RC_ASSERT(same(*overlay, *exact));
}

}  // namespace
}  // namespace edgeland
