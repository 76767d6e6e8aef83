// Cases for clip/ lines the rest of the suite did not reach (issue 18, scripts/coverage.sh).
// Each asserts a documented property; expectations are worked out by hand from clip.hpp's
// contracts, not taken from a run.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/validate.hpp"

namespace edgeland {
namespace {

const ClipOptions kChecked{.checked = true};

// Canonical form as clip.hpp states it: each ring starts at its lexicographically smallest
// vertex; the set sorted (by that vertex, then the rest).
PolygonSet canonical(PolygonSet set) {
  for (Polygon& p : set) std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
  std::sort(set.begin(), set.end());
  return set;
}

// clip.hpp: InternalError carries the inputs as WKT beside the message, and is an Error.
TEST(InternalError, CarriesTheInputsAsWkt) {
  const std::string subject = "MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)))";
  const InternalError e("union: invalid output", subject, "MULTIPOLYGON EMPTY");
  EXPECT_EQ(e.subject_wkt, subject);
  EXPECT_EQ(e.clip_wkt, "MULTIPOLYGON EMPTY");
  EXPECT_NE(std::string(e.what()).find("union: invalid output"), std::string::npos);
  const Error* base = &e;
  EXPECT_EQ(base->what(), e.what());
}

// clip.hpp (import_polygons) and errors.hpp: a coordinate beyond the bound in a hole is a
// CoordinateOutOfRange naming the rings operand, the polygon (entry 1 here), the ring within it
// (2: its second hole) and the vertex's index in that ring (2); the message names the ring.
TEST(ImportPolygons, CoordinateOutOfRangeInAHoleNamesPolygonRingAndVertex) {
  const Point64 bad{23, kCoordBound + 1};
  const std::vector<std::vector<Ring>> polygons{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}},
                                                {{{20, 0}, {30, 0}, {30, 10}, {20, 10}},
                                                 {{26, 2}, {28, 2}, {28, 4}, {26, 4}},
                                                 {{22, 2}, {24, 2}, bad, {22, 4}}}};
  try {
    const ClipResult r = import_polygons(polygons);
    FAIL() << "imported " << r.polygons.size() << " polygons";
  } catch (const CoordinateOutOfRange& e) {
    EXPECT_EQ(e.operand, Operand::kRings);
    EXPECT_EQ(e.polygon, 1u);
    EXPECT_EQ(e.ring, 2u);
    EXPECT_EQ(e.vertex, 2u);
    EXPECT_EQ(e.where, bad);
    EXPECT_EQ(std::string(e.what()),
              "invalid rings: coordinate-out-of-range: polygon 1 ring 2 vertex 2 at "
              "(23 2147483648)");
  }
}

// The same in an exterior (ring 0): the message is validate()'s wording, without a ring.
TEST(ImportPolygons, CoordinateOutOfRangeInAnExteriorIsRingZero) {
  const Point64 bad{-kCoordBound - 1, 0};
  const std::vector<std::vector<Ring>> polygons{
      {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}},
      {{{20, 0}, bad, {30, 10}, {20, 10}}, {{22, 2}, {24, 2}, {24, 4}, {22, 4}}}};
  try {
    const ClipResult r = import_polygons(polygons);
    FAIL() << "imported " << r.polygons.size() << " polygons";
  } catch (const CoordinateOutOfRange& e) {
    EXPECT_EQ(e.polygon, 1u);
    EXPECT_EQ(e.ring, 0u);
    EXPECT_EQ(e.vertex, 1u);
    EXPECT_EQ(std::string(e.what()),
              "invalid rings: coordinate-out-of-range: polygon 1 vertex 1 at (-2147483648 0)");
  }
}

// clip.hpp: import_to_valid_set returns import_polygons' polygons. A 10 x 10 square with a
// 2 x 2 hole (given clockwise, as OGC writes holes) covers 100 - 4 = 96; the result is
// hole-free, valid, and keeps that area exactly (hole splitting cuts between vertices).
TEST(ImportToValidSet, SquareWithAHoleGivesImportPolygonsPieces) {
  const std::vector<std::vector<Ring>> polygons{
      {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{4, 4}, {4, 6}, {6, 6}, {6, 4}}}};
  const ValidClipResult valid = import_to_valid_set(polygons, kChecked);
  const ClipResult plain = import_polygons(polygons, kChecked);
  EXPECT_EQ(valid.set.polygons(), plain.polygons);
  EXPECT_TRUE(validate(valid.set.polygons()).ok());
  EXPECT_GE(valid.set.polygons().size(), 2u);  // a hole-free cover of an annulus
  EXPECT_EQ(twice_signed_area(valid.set.polygons()), Int128{2 * 96});
}

// Twelve thin triangles around the origin, touching only there: a valid set whose plane graph
// has a vertex of degree 24 (more half-edges than the insertion sort of one vertex handles).
// Intersected with a box around them all, every triangle comes back unchanged (in canonical
// form): no edge meets the box or another triangle except at the shared corner.
TEST(ClipIntersection, FanOfTwelveTrianglesSharingOneCorner) {
  // Directions about 15 degrees apart, counter-clockwise from +x; triangle k spans the sector
  // from direction 2k to 2k + 1, so the sectors are disjoint.
  const std::array<Point64, 24> d{
      {{100, 0},   {97, 26},   {87, 50},  {71, 71},  {50, 87},  {26, 97},   {0, 100},   {-26, 97},
       {-50, 87},  {-71, 71},  {-87, 50}, {-97, 26}, {-100, 0}, {-97, -26}, {-87, -50}, {-71, -71},
       {-50, -87}, {-26, -97}, {0, -100}, {26, -97}, {50, -87}, {71, -71},  {87, -50},  {97, -26}}};
  PolygonSet fan;
  for (std::size_t k = 0; k < 12; ++k) fan.push_back({{0, 0}, d[2 * k], d[2 * k + 1]});
  ASSERT_TRUE(validate(fan).ok());
  const PolygonSet box{{{-200, -200}, {200, -200}, {200, 200}, {-200, 200}}};
  const ClipResult r = clip(ClipOp::kIntersection, fan, box, kChecked);
  EXPECT_EQ(r.polygons, canonical(fan));
  EXPECT_EQ(r.stats.intersections, 0u);
}

}  // namespace
}  // namespace edgeland
