// Landscape::remove (landscape.hpp): polygons named by id and cell come out exactly as a carve of
// their own region would take them out (the same state hash: same polygons, ids and tree), with
// no shape validated; a name the landscape does not hold changes nothing.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "edgeland/spatial/landscape.hpp"
#include "landscape_cases.hpp"

namespace edgeland::test {
namespace {

std::vector<PolygonRef> refs_of(const Landscape& l, std::uint64_t pick) {
  std::vector<PolygonRef> out;
  std::uint64_t k = 0;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    if ((pick >> (k++ % 64)) & 1u) out.push_back({v.id, v.cell});
    return true;
  });
  return out;
}

PolygonSet polygons_of(const Landscape& l, const std::vector<PolygonRef>& refs) {
  PolygonSet out;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    for (const PolygonRef& r : refs)
      if (r.id == v.id) out.push_back(*v.polygon);
    return true;
  });
  return out;
}

// Removing any choice of polygons equals carving their union (their region): same state.
RC_GTEST_PROP(LandscapeRemoveProperty, IsACarveOfTheirOwnRegion, ()) {
  const LandscapeCase c = *landscape_case(10);
  Landscape l(c.world, c.fill, c.config);
  l.set_checked(true);
  for (const LandscapeEdit& e : c.edits) apply(l, e);
  const std::vector<PolygonRef> refs = refs_of(l, *rc::gen::arbitrary<std::uint64_t>());
  RC_PRE(!refs.empty());
  Landscape carved = l;
  const ChangeSet by_carve = carved.carve(ValidSet(polygons_of(l, refs)));
  const ChangeSet by_remove = l.remove(refs);
  RC_ASSERT(l.state_hash() == carved.state_hash());
  RC_ASSERT(by_remove.removed == by_carve.removed);
  RC_ASSERT(by_remove.cells == by_carve.cells);
  RC_ASSERT(l.check().ok());
}

TEST(LandscapeRemove, ANameItDoesNotHoldChangesNothing) {
  Landscape l({{0, 0}, {256, 256}}, 1);
  l.carve(PolygonSet{{{10, 10}, {100, 10}, {100, 100}, {10, 100}}});
  std::vector<PolygonRef> refs = refs_of(l, ~std::uint64_t{0});
  const std::uint64_t hash = l.state_hash();
  refs.push_back({987654, refs.front().cell});
  try {
    l.remove(refs);
    FAIL() << "an unknown id was removed";
  } catch (const UnknownPolygon& e) {
    EXPECT_EQ(e.id, 987654u);
    EXPECT_EQ(e.cell, refs.front().cell);
  }
  refs.back() = {refs.front().id, Box64{{1, 1}, {2, 2}}};  // no cell has that box
  EXPECT_THROW(l.remove(refs), UnknownPolygon);
  EXPECT_EQ(l.state_hash(), hash);
  EXPECT_TRUE(l.remove(std::vector<PolygonRef>{}).empty());
}

TEST(LandscapeRemove, TheLogReplaysIt) {
  Landscape l({{0, 0}, {256, 256}}, kEmpty);
  l.start_log();
  l.fill(PolygonSet{{{10, 10}, {100, 10}, {100, 100}, {10, 100}}}, 2);
  l.fill(PolygonSet{{{150, 150}, {200, 150}, {200, 200}, {150, 200}}}, 3);
  std::vector<PolygonRef> refs;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    if (v.material == Material(3)) refs.push_back({v.id, v.cell});
    return true;
  });
  l.remove(refs);
  EXPECT_EQ(l.twice_area(3), 0);
  EXPECT_EQ(l.twice_area(2), 2 * 90 * 90);
  EXPECT_NE(l.log().find("carve"), std::string::npos);
}

}  // namespace
}  // namespace edgeland::test
