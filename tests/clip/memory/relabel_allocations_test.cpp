// relabel() reuses its working storage (kernel/internal/.../scratch.hpp): once an overlay of a
// size has run, the same overlay allocates nothing but its result (issue 28: a landscape edit
// calls it for every cell it touches, many times a frame). Counted by the counting allocation
// functions (tests/support/allocation_meter.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "allocation_meter.hpp"
#include "edgeland/clip/relabel.hpp"

namespace edgeland {
namespace {

// A 32-gon of radius r round c, vertices rounded (the test's own input, not library
// arithmetic), as a game's explosion.
Polygon blast(Point64 c, double r) {
  Polygon p;
  for (int i = 0; i < 32; ++i) {
    const double a = 2 * std::numbers::pi * i / 32;
    p.push_back({c.x + std::llround(r * std::cos(a)), c.y + std::llround(r * std::sin(a))});
  }
  return p;
}

const Box64 kCell{{0, 0}, {256, 256}};
const std::vector<RegionLabel>& carve_table() {
  static const std::vector<RegionLabel> table(256, 0);
  return table;
}

// The heap blocks a labeled set owns: its polygon vector, each polygon, its label vector.
std::size_t blocks_of(const LabeledSet& s) {
  const std::size_t n = s.labels.size();
  return n == 0 ? 0 : n + 2;
}

// A cell of rock (1) and ore (2) worn by a few earlier blasts: a landscape cell's content.
LabeledSet worn_cell() {
  LabeledSet cell{ValidSet(PolygonSet{{{0, 0}, {256, 0}, {256, 256}, {0, 256}}}), {1}};
  const std::vector<RegionLabel> ore(256, 2);
  cell = relabel(cell.set, cell.labels, ValidSet(PolygonSet{blast({200, 60}, 30)}), kCell, ore)
             .regions;
  for (Point64 c : {Point64{60, 70}, Point64{150, 180}, Point64{230, 230}})
    cell = relabel(cell.set, cell.labels, ValidSet(PolygonSet{blast(c, 40)}), kCell, carve_table())
               .regions;
  return cell;
}

// Allocations of one overlay beyond the blocks of its result.
std::size_t extra_allocations(const LabeledSet& cell, const ValidSet& shape, LabeledSet* out) {
  const std::size_t before = fuzz::allocations_made();
  LabeledClipResult r = relabel(cell.set, cell.labels, shape, kCell, carve_table());
  const std::size_t made = fuzz::allocations_made() - before;
  const std::size_t result = blocks_of(r.regions);
  if (out) *out = std::move(r.regions);
  return made - std::min(made, result);
}

TEST(RelabelAllocations, ARepeatedOverlayAllocatesOnlyItsResult) {
  const LabeledSet cell = worn_cell();
  // Crosses the rock's holes, the ore and the cell's side: hot pixels, moved edges, a window.
  const ValidSet shape(PolygonSet{blast({190, 100}, 70)});
  // Warm-up: the scratch arrays grow to what the call needs (a few grow again when the stacks
  // of spare arrays hand them to another use of different size, about a dozen calls here).
  std::size_t warming = 0;
  for (int i = 0; i < 30; ++i) warming += extra_allocations(cell, shape, nullptr);
  RecordProperty("allocations_while_warming", static_cast<int>(warming));
  for (int i = 0; i < 10; ++i) EXPECT_EQ(extra_allocations(cell, shape, nullptr), 0u) << i;
}

TEST(RelabelAllocations, ASequenceOfBlastsAllocatesNearlyOnlyItsResultsOnceWarm) {
  // Forty blasts over the cell, each into the result of the one before, five times: from the
  // fifth round on the calls meet only sizes the earlier ones have seen. Before the scratch
  // storage covered every stage, the second round of the same forty overlays made 7,871
  // allocations beyond their results (about 200 each); what is left is a rare array handed to a
  // use it is too small for.
  std::vector<ValidSet> shapes;
  for (int i = 0; i < 40; ++i)
    shapes.emplace_back(PolygonSet{blast({(i * 97) % 256, (i * 61) % 256}, 20 + (i * 13) % 40)});
  std::size_t extra = 0;
  for (int round = 0; round < 5; ++round) {
    LabeledSet cell = worn_cell();
    extra = 0;
    for (const ValidSet& shape : shapes) {
      LabeledSet next;
      extra += extra_allocations(cell, shape, &next);
      cell = std::move(next);
    }
  }
  RecordProperty("allocations_in_fifth_round", static_cast<int>(extra));
  EXPECT_LE(extra, 4u);
}

// relabel_near() on a cell of several regions with a small blast in one corner, once warm:
// beyond what relabel() of the same overlay allocates besides its result, merging the left-out
// pieces back costs their copies (part of the result) and two arrays, the merged result's
// vectors, which replace the pipeline's.
TEST(RelabelAllocations, ANearOverlayAllocatesAtMostTwoArraysMoreThanRelabel) {
  const LabeledSet cell = worn_cell();
  ASSERT_GT(cell.labels.size(), 2u);
  const ValidSet shape(PolygonSet{blast({240, 12}, 6)});
  auto near_extra = [&] {
    const std::size_t before = fuzz::allocations_made();
    const LabeledClipResult r = relabel_near(cell.set, cell.labels, shape, kCell, carve_table());
    const std::size_t made = fuzz::allocations_made() - before;
    return made - std::min(made, blocks_of(r.regions));
  };
  for (int i = 0; i < 30; ++i) {
    near_extra();
    extra_allocations(cell, shape, nullptr);
  }
  for (int i = 0; i < 10; ++i) {
    const std::size_t full = extra_allocations(cell, shape, nullptr);
    EXPECT_LE(near_extra(), full + 2) << i;
  }
}

}  // namespace
}  // namespace edgeland
