// Inputs with hundreds of crossings: two spiky star polygons (random points in angular order
// around two nearby centres), so that long spikes of one cross many spikes of the other. These
// take the paths snap rounding uses only for many hot pixels (clip/src/segment_grid.hpp: every
// hot pixel and vertex asks the grid for the segments near it; the re-check of moved fragments
// walks them through a grid of their own), which small property-test inputs rarely reach. Every
// result is checked against the exact CGAL reference (accuracy_contract.hpp).
#include <gtest/gtest.h>

#include <random>

#include "accuracy_contract.hpp"
#include "checked_clip.hpp"
#include "shape_builders.hpp"

namespace edgeland::test {
namespace {

Polygon spiky_star(std::mt19937_64& rng, Point64 centre, std::int64_t r, int points) {
  std::uniform_int_distribution<std::int64_t> d(-r, r);
  std::vector<Point64> pts;
  for (int i = 0; i < points; ++i) pts.push_back({centre.x + d(rng), centre.y + d(rng)});
  return star_polygon(centre, pts);
}

class ManyCrossings : public ::testing::TestWithParam<int> {};

TEST_P(ManyCrossings, SpikyStarsMeetTheAccuracyContract) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(GetParam()));
  // Small coordinates make many crossings land off the grid near other vertices; large ones
  // make rounding rare relative to the spacing. Both are run.
  const std::int64_t r = GetParam() % 2 == 0 ? 400 : 40'000'000;
  const PolygonSet a{spiky_star(rng, {0, 0}, r, 160)};
  const PolygonSet b{spiky_star(rng, {r / 7, r / 9}, r, 160)};
  ASSERT_TRUE(validate(a).ok());
  ASSERT_TRUE(validate(b).ok());
  for (ClipOp op : {ClipOp::kUnion, ClipOp::kIntersection, ClipOp::kDifference, ClipOp::kXor}) {
    const Outcome o = run_clip(op, a, b);
    ASSERT_TRUE(o.ok()) << o.error;
    // Enough crossings that the grid paths are taken (more than 64 hot pixels, a fair share
    // of the 320 segments).
    EXPECT_GT(o.result->stats.vertices_snapped, 64u) << op_name(op);
    ContractOptions options;
    options.random_points = 2000;
    const ContractReport report = check_clip(op, a, b, *o.result, options);
    EXPECT_TRUE(report.ok()) << report.failure;
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, ManyCrossings, ::testing::Range(1, 7));

}  // namespace
}  // namespace edgeland::test
