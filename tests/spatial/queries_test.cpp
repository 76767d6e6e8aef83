// The queries' contracts that issue 27 found loose: one rule for coordinates (point 9).
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "edgeland/spatial/landscape.hpp"

namespace edgeland::test {
namespace {

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

}  // namespace
}  // namespace edgeland::test
