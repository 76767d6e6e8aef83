// The queries' contracts that issue 27 found loose: one rule for coordinates (point 9), views
// that outlive the landscape they came from (point 7), and the world's border, which is no
// surface for rays (point 15).
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "edgeland/spatial/landscape.hpp"

namespace edgeland::test {
namespace {

Polygon box_polygon(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// Runs the query, which must throw CoordinateOutOfRange for the argument named `message`.
template <class Query>
void expect_refused(Query&& query, std::size_t vertex, Point64 where, const std::string& message) {
  try {
    query();
    ADD_FAILURE() << "answered: " << message;
  } catch (const CoordinateOutOfRange& e) {
    EXPECT_EQ(e.operand, Operand::kQuery);
    EXPECT_EQ(e.vertex, vertex);
    EXPECT_EQ(e.where, where);
    EXPECT_EQ(std::string(e.what()), "invalid query: coordinate-out-of-range: " + message);
  }
}

// Point 9: material_at({INT64_MIN, INT64_MAX}) answered 0 and polygons_in took any box, though
// the README said out-of-range coordinates throw in queries too; a bad ray end was reported as
// "polygon 0 vertex 0". Now every query refuses a coordinate beyond the bound the same way:
// CoordinateOutOfRange, operand kQuery, `vertex` the argument's index, the message its name.
TEST(LandscapeQueries, EveryQueryRefusesACoordinateBeyondTheBound) {
  Landscape l({{0, 0}, {100, 100}}, 1);
  const std::uint64_t before = l.state_hash();
  constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  const Point64 far{kMin, kMax}, beyond{kCoordBound + 1, 0}, origin{0, 0};
  const std::string far_text = "(" + std::to_string(kMin) + " " + std::to_string(kMax) + ")";
  const std::string beyond_text = "(2147483648 0)";
  const auto nothing = [](const auto&) { return true; };
  expect_refused([&] { l.material_at(far); }, 0, far, "point at " + far_text);
  expect_refused([&] { l.crossings(origin, beyond); }, 1, beyond, "to at " + beyond_text);
  expect_refused([&] { l.raycast(beyond, origin); }, 0, beyond, "from at " + beyond_text);
  const Box64 to_beyond{origin, beyond}, from_far{far, origin};
  expect_refused([&] { l.overlaps(to_beyond); }, 1, beyond, "box max at " + beyond_text);
  expect_refused([&] { l.polygons_in(from_far, nothing); }, 0, far, "box min at " + far_text);
  expect_refused([&] { l.cells_in(to_beyond, nothing); }, 1, beyond, "box max at " + beyond_text);
  // The bound itself is in range; an inverted box is no error and meets nothing.
  EXPECT_EQ(l.material_at({kCoordBound, -kCoordBound}), kEmpty);
  std::size_t met = 0;
  l.polygons_in(Box64{{50, 50}, {10, 10}}, [&](const PolygonView&) { return ++met, true; });
  EXPECT_EQ(met, 0u);
  EXPECT_EQ(l.state_hash(), before);
}

// Point 7: PolygonView::polygon pointed into the cell, which the next edit of the landscape
// freed (ASan: heap-use-after-free), though the header said "valid while the landscape
// lives". A view now shares its cell: the polygon outlives edits and the landscape itself. (The
// sanitizer build runs this test: a dangling view is an ASan error there.)
TEST(PolygonView, ThePolygonOutlivesEditsAndTheLandscape) {
  std::vector<PolygonView> kept;
  std::vector<Polygon> copies;
  {
    Landscape l({{0, 0}, {1000, 1000}});
    for (int i = 0; i < 6; ++i)
      l.fill(PolygonSet{box_polygon(100 * i, 0, 100 * i + 60, 50)}, 1 + i % 3);
    l.polygons_in(l.world(), [&](const PolygonView& v) {
      kept.push_back(v);
      copies.push_back(*v.polygon);
      return true;
    });
    ASSERT_EQ(kept.size(), 6u);
    l.fill(PolygonSet{box_polygon(0, 0, 1000, 1000)}, 4);  // every cell replaced
    l.carve(PolygonSet{box_polygon(0, 0, 1000, 1000)});
    for (std::size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(*kept[i].polygon, copies[i]);
  }
  for (std::size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(*kept[i].polygon, copies[i]);
}

// Point 15: the README's raycast({0, 4040}, {8000, 4040}) in a world filled with rock "hit" the
// world's west border at t = 0, as would any ray from the world's min edge. The world's border
// is no surface for rays now: a ray entering or leaving the world reports no change there.
TEST(LandscapeRays, TheWorldsBorderIsNoSurface) {
  Landscape world({{0, 0}, {8192, 8192}}, 1);
  world.carve(PolygonSet{box_polygon(3990, 4000, 4060, 4070)});
  // From the west edge, inside rock: through the blast, the hit is its far wall.
  const auto hit = world.raycast({0, 4040}, {8000, 4040});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->rounded, (Point64{4060, 4040}));
  EXPECT_EQ(hit->before, kEmpty);
  EXPECT_EQ(hit->after, 1);
  // The whole profile from outside the world to outside it: only the blast's two walls.
  const std::vector<MaterialCrossing> all = world.crossings({-500, 4040}, {9000, 4040});
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].rounded, (Point64{3990, 4040}));
  EXPECT_EQ(all[0].before, 1);
  EXPECT_EQ(all[0].after, kEmpty);
  EXPECT_EQ(all[1].rounded, (Point64{4060, 4040}));
  // A ray from outside into rock, which it never leaves inside the world: nothing to hit.
  EXPECT_FALSE(world.raycast({-100, 100}, {200, 100}).has_value());
  // Along the world's min edges (inside, by the half-open rule): the blast is not on them, so
  // the ray sees rock throughout.
  EXPECT_TRUE(world.crossings({0, 0}, {8192, 0}).empty());
  EXPECT_TRUE(world.crossings({0, 0}, {0, 8192}).empty());
  // Inside the world nothing changed: a ray from empty space hits the first surface.
  const auto from_blast = world.raycast({4000, 4040}, {0, 4040});
  ASSERT_TRUE(from_blast.has_value());
  EXPECT_EQ(from_blast->rounded, (Point64{3990, 4040}));
}

}  // namespace
}  // namespace edgeland::test
