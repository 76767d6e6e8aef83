// Landscape::relabel (issue 27, point 11): the general edit, material -> material under the
// shape in one call, against the sequence of replace() calls that does the same, and with the
// edits' guarantees (strong guarantee, change set, log).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "edgeland/kernel/wkt_writer.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::test {
namespace {

Polygon box_polygon(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// The replace() calls that make the map's parallel assignment one at a time (the classic
// sequentialisation of parallel moves): a pair goes once no other pending pair still reads its
// target; a cycle (a swap) first moves one of its sources to a spare material (spare,
// spare + 1, ...: materials the world does not hold).
std::vector<std::pair<Material, Material>> replaces_for(const MaterialMap& map,
                                                        std::uint8_t spare) {
  std::map<std::uint8_t, std::uint8_t> pending;
  for (int m = 0; m < 256; ++m)
    if (map[m].value() != m) pending[static_cast<std::uint8_t>(m)] = map[m].value();
  std::vector<std::pair<Material, Material>> out;
  while (!pending.empty()) {
    bool moved = false;
    for (auto it = pending.begin(); it != pending.end(); ++it)
      if (!pending.count(it->second)) {
        out.push_back({it->first, it->second});
        pending.erase(it);
        moved = true;
        break;
      }
    if (moved) continue;
    const auto [from, to] = *pending.begin();  // every target is read: a cycle
    out.push_back({from, spare});
    pending.erase(from);
    pending[spare] = to;
    ++spare;  // a fresh one for the next cycle
  }
  return out;
}

// A world of axis-aligned boxes: every intersection is an integer point, so the regions of a
// relabel and of its replaces are exactly equal, whatever the order of the edits.
Landscape boxes_world(const std::vector<std::pair<Box64, int>>& fills) {
  Landscape l({{0, 0}, {96, 96}}, 1, LandscapeConfig{.edge_cap = 32});
  l.set_checked(true);
  for (const auto& [b, m] : fills)
    l.fill(PolygonSet{box_polygon(b.min.x, b.min.y, b.max.x, b.max.y)}, m);
  return l;
}

rc::Gen<Box64> box_in_world() {
  return rc::gen::exec([] {
    const std::int64_t x0 = *rc::gen::inRange<std::int64_t>(0, 90);
    const std::int64_t y0 = *rc::gen::inRange<std::int64_t>(0, 90);
    const std::int64_t x1 = *rc::gen::inRange<std::int64_t>(x0 + 1, 97);
    const std::int64_t y1 = *rc::gen::inRange<std::int64_t>(y0 + 1, 97);
    return Box64{{x0, y0}, {x1, y1}};
  });
}

// Same material at every unit square (material_at of its corner, the half-open rule) and the
// same area per material: the same regions.
void expect_same_regions(const Landscape& a, const Landscape& b) {
  for (std::int64_t x = 0; x < 96; ++x)
    for (std::int64_t y = 0; y < 96; ++y) RC_ASSERT(a.material_at({x, y}) == b.material_at({x, y}));
  for (int m = 0; m < 256; ++m) RC_ASSERT(a.twice_area(m) == b.twice_area(m));
}

// One relabel leaves the regions that the equivalent replaces leave, and its change set's area
// deltas are the change of twice_area.
RC_GTEST_PROP(LandscapeRelabelProperty, EqualsTheReplacesItStandsFor, ()) {
  std::vector<std::pair<Box64, int>> fills;
  const int count = *rc::gen::inRange(0, 8);
  for (int i = 0; i < count; ++i) fills.push_back({*box_in_world(), *rc::gen::inRange(0, 6)});
  const Landscape before = boxes_world(fills);
  MaterialMap map;
  for (int m = 0; m < 6; ++m) map.set(m, *rc::gen::inRange(0, 6));
  const Box64 b = *box_in_world();
  const PolygonSet shape{box_polygon(b.min.x, b.min.y, b.max.x, b.max.y)};

  RC_LOG() << "shape " << to_wkt(shape) << "\n";
  Landscape one = before;
  const ChangeSet changes = one.relabel(shape, map);
  Landscape many = before;
  for (const auto& [from, to] : replaces_for(map, 200)) many.replace(shape, from, to);
  expect_same_regions(one, many);
  RC_ASSERT(one.check().ok());
  for (const auto& [m, delta] : changes.twice_area_delta)
    RC_ASSERT(one.twice_area(m) - before.twice_area(m) == delta);
}

// The four edits are relabels with their maps: the same state, bit for bit.
TEST(LandscapeRelabel, TheFourEditsAreRelabelsWithTheirMaps) {
  Landscape base({{0, 0}, {1000, 1000}}, 1);
  base.fill(PolygonSet{box_polygon(100, 100, 600, 400)}, 2);
  base.fill(PolygonSet{box_polygon(300, 300, 700, 900)}, 3);
  base.carve(PolygonSet{{{0, 0}, {400, 50}, {50, 400}}});
  const PolygonSet shape{{{200, 150}, {800, 250}, {650, 750}, {150, 600}}};
  const auto same = [&](auto&& edit, const MaterialMap& map) {
    Landscape a = base, b = base;
    edit(a);
    b.relabel(shape, map);
    EXPECT_EQ(a.state_hash(), b.state_hash());
  };
  same([&](Landscape& l) { l.carve(shape); }, MaterialMap::uniform(kEmpty));
  same([&](Landscape& l) { l.fill(shape, 4); }, MaterialMap::uniform(4));
  same([&](Landscape& l) { l.fill_empty(shape, 4); }, MaterialMap().set(kEmpty, 4));
  same([&](Landscape& l) { l.replace(shape, 2, 3); }, MaterialMap().set(2, 3));
}

// "An explosion that spares bedrock": one call where a game wrote one replace per material,
// and a swap, which no single replace can do.
TEST(LandscapeRelabel, AnExplosionThatSparesBedrockAndASwap) {
  Landscape l({{0, 0}, {1000, 1000}}, 1);
  l.fill(PolygonSet{box_polygon(0, 0, 1000, 200)}, 9);  // bedrock
  l.fill(PolygonSet{box_polygon(400, 200, 600, 500)}, 2);
  const PolygonSet blast{box_polygon(300, 100, 700, 400)};
  l.relabel(blast, MaterialMap::uniform(kEmpty).set(9, 9));
  EXPECT_EQ(l.material_at({500, 150}), 9);  // bedrock stays
  EXPECT_EQ(l.material_at({500, 300}), kEmpty);
  EXPECT_EQ(l.material_at({350, 300}), kEmpty);
  EXPECT_EQ(l.material_at({500, 450}), 2);  // outside the blast
  l.relabel(PolygonSet{box_polygon(0, 0, 1000, 1000)}, MaterialMap().set(1, 2).set(2, 1));
  EXPECT_EQ(l.material_at({500, 450}), 1);
  EXPECT_EQ(l.material_at({100, 450}), 2);
  EXPECT_TRUE(l.check().ok());
}

// The strong guarantee: a shape the kernel refuses changes nothing.
TEST(LandscapeRelabel, ARefusedShapeChangesNothing) {
  Landscape l({{0, 0}, {1000, 1000}}, 1);
  l.fill(PolygonSet{box_polygon(100, 100, 600, 400)}, 2);
  const std::uint64_t before = l.state_hash();
  const PolygonSet bow_tie{{{0, 0}, {100, 100}, {100, 0}, {0, 100}}};
  EXPECT_THROW(l.relabel(bow_tie, MaterialMap::uniform(kEmpty)), InvalidInput);
  const PolygonSet far{box_polygon(0, 0, kCoordBound + 1, 10)};
  EXPECT_THROW(l.relabel(far, MaterialMap::uniform(kEmpty)), CoordinateOutOfRange);
  EXPECT_EQ(l.state_hash(), before);
}

// The log records a relabel as one line that replays to the same state (io's reader reads it:
// tests/io/landscape_log_test.cpp).
TEST(LandscapeRelabel, TheLogRecordsTheChangedPairs) {
  Landscape l({{0, 0}, {100, 100}}, 1);
  l.start_log();
  l.relabel(PolygonSet{box_polygon(10, 10, 20, 20)}, MaterialMap::uniform(kEmpty).set(3, 7));
  const std::string log = l.log();
  const std::string last = log.substr(log.rfind("relabel"));
  // The pairs that change a material, ascending: 0 stays 0 and is not written.
  EXPECT_EQ(last.substr(0, 24), "relabel 1 0 2 0 3 7 4 0 ");
  EXPECT_NE(last.find(" 255 0 MULTIPOLYGON"), std::string::npos);
}

}  // namespace
}  // namespace edgeland::test
