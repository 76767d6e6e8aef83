// Polygon ids through splits and merges (landscape.hpp, IDS; spatial/README.md, I6 and "Ids"):
// a polygon whose ring and material an edit did not change keeps its id, also when the edit
// moves it into another cell, and the change set names exactly the ids that left and arrived.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "edgeland/spatial/landscape.hpp"

namespace edgeland::test {
namespace {

using PolygonKey = std::pair<Material, Polygon>;

std::map<PolygonKey, PolygonId> ids_by_polygon(const Landscape& l) {
  std::map<PolygonKey, PolygonId> out;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    out[{v.material, *v.polygon}] = v.id;
    return true;
  });
  return out;
}

std::map<PolygonKey, Box64> cells_by_polygon(const Landscape& l) {
  std::map<PolygonKey, Box64> out;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    out[{v.material, *v.polygon}] = v.cell;
    return true;
  });
  return out;
}

// The ids of `from` whose polygons are not in `to`, ascending (a change set's order).
std::vector<PolygonId> ids_missing_in(const std::map<PolygonKey, PolygonId>& from,
                                      const std::map<PolygonKey, PolygonId>& to) {
  std::vector<PolygonId> out;
  for (const auto& [key, id] : from)
    if (!to.count(key)) out.push_back(id);
  std::sort(out.begin(), out.end());
  return out;
}

// Applies the edit and checks the id contract against the state before it; returns how many
// polygons the edit left unchanged (so a case can assert it tests something).
std::size_t carve_keeping_ids(Landscape& l, const PolygonSet& shape) {
  const std::map<PolygonKey, PolygonId> before = ids_by_polygon(l);
  const ChangeSet cs = l.carve(shape);
  const std::map<PolygonKey, PolygonId> after = ids_by_polygon(l);
  std::size_t unchanged = 0;
  for (const auto& [key, id] : after) {
    const auto it = before.find(key);
    if (it == before.end()) continue;
    ++unchanged;
    EXPECT_EQ(id, it->second) << "an unchanged polygon of material " << int(key.first.value())
                              << " got a new id";
  }
  EXPECT_EQ(cs.removed, ids_missing_in(before, after));
  std::vector<PolygonId> added;
  for (const ChangeSet::Added& a : cs.added) added.push_back(a.id);
  EXPECT_EQ(added, ids_missing_in(after, before));
  const LandscapeReport report = l.check();
  EXPECT_TRUE(report.ok()) << report.problems.front();
  return unchanged;
}

// Shrunk by RapidCheck from LandscapeProperty.EditsKeepEveryInvariantAndReportWhatChanged. The
// third carve crowds the one cell past the edge cap. As one cell, the content bridged the
// carve's new hole through a small polygon far to the west, which the split then brought back
// unchanged. Ids were matched against that one-cell content, which the edit threw away, so the
// polygon came back with a fresh id.
TEST(LandscapeIds, AnUnchangedPolygonKeepsItsIdWhenTheEditSplitsItsCell) {
  LandscapeConfig config;
  config.tree = TreeKind::kQuadtree;
  config.edge_cap = 40;
  config.merge_below = 13;
  config.min_cell_size = 1;
  Landscape l({{-300, -300}, {-44, -172}}, 1, config);
  l.set_checked(true);
  l.carve(PolygonSet{{{-396, -396}, {-268, -396}, {-268, -268}}});
  l.carve(PolygonSet{{{-295, -266}, {-292, -266}, {-295, -265}},
                     {{-299, -270}, {-298, -270}, {-297, -267}, {-298, -267}, {-299, -269}},
                     {{-298, -277}, {-299, -278}, {-299, -279}, {-297, -279}}});
  ASSERT_EQ(l.stats().cells, 1u);
  const std::size_t unchanged = carve_keeping_ids(l, PolygonSet{{{-176, -242},
                                                                 {-168, -243},
                                                                 {-167, -243},
                                                                 {-162, -242},
                                                                 {-167, -241},
                                                                 {-174, -240},
                                                                 {-176, -241}}});
  // What the case is about: the cell split, and some polygons stayed as they were.
  EXPECT_GT(l.stats().cells, 1u);
  EXPECT_GT(unchanged, 0u);
}

// The other way: an untouched square in one quadrant keeps its id when emptying another
// quadrant merges the four back into one cell.
TEST(LandscapeIds, AnUnchangedPolygonKeepsItsIdWhenItsCellMerges) {
  LandscapeConfig config;
  config.edge_cap = 32;
  config.merge_below = 24;
  config.min_cell_size = 1;
  Landscape l({{0, 0}, {256, 256}}, kEmpty, config);
  l.set_checked(true);
  const Polygon square{{10, 10}, {20, 10}, {20, 20}, {10, 20}};
  l.fill(PolygonSet{square}, 2);
  // A staircase of 30 edges in the north-east quadrant: with the square's 4 the world cell
  // passes the cap of 32 and splits once into quadrants; the staircase alone fits in its own.
  Polygon stairs{{140, 140}};
  for (std::int64_t i = 0; i < 14; ++i) {
    stairs.push_back({150 + 4 * i, 140 + 4 * i});
    stairs.push_back({150 + 4 * i, 144 + 4 * i});
  }
  stairs.push_back({140, 196});
  l.fill(PolygonSet{stairs}, 1);
  ASSERT_EQ(l.stats().cells, 4u);
  ASSERT_EQ(cells_by_polygon(l).at({2, square}), (Box64{{0, 0}, {128, 128}}));
  const std::size_t unchanged =
      carve_keeping_ids(l, PolygonSet{{{128, 128}, {256, 128}, {256, 256}, {128, 256}}});
  EXPECT_EQ(l.stats().cells, 1u);
  EXPECT_EQ(unchanged, 1u);  // the square, alone
  EXPECT_EQ(cells_by_polygon(l).at({2, square}), l.world());
}

}  // namespace
}  // namespace edgeland::test
