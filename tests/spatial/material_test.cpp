// Material (spatial/material.hpp): a number outside 0..255 can never pass as a material
// silently (issue 27, point 8). As a uint8_t, fill(shape, 260) filled material 4 and
// replace(shape, 1, -1) wrote 255, with no warning even under -Wconversion; both calls compiled
// and changed the world. Now the conversion throws InvalidMaterial before the edit runs.
#include "edgeland/spatial/material.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <type_traits>
#include <unordered_set>

#include "edgeland/spatial/landscape.hpp"

namespace edgeland::test {
namespace {

// Whether Material(N) is a constant expression: an out-of-range constant does not compile.
template <long long N>
constexpr bool kConstantMaterial = requires {
  typename std::integral_constant<std::uint8_t, Material(N).value()>;
};
static_assert(kConstantMaterial<0> && kConstantMaterial<255>);
static_assert(!kConstantMaterial<256> && !kConstantMaterial<-1>);
// Neither truth values nor characters are material numbers; a Material is no integer.
static_assert(!std::is_convertible_v<bool, Material>);
static_assert(!std::is_convertible_v<char, Material>);
static_assert(!std::is_convertible_v<Material, int>);
static_assert(std::is_convertible_v<std::uint8_t, Material>);
static_assert(Material(7).value() == 7 && Material(7) == 7 && Material(3) < Material(7));
static_assert(!kEmpty.solid() && Material(1).solid());

// A game's unscoped enumeration of materials converts like its numbers (issue 36, point 7: it
// was a compile error); an out-of-range enumerator is refused like any number; a scoped one
// still does not convert (tests/spatial/material_scoped_enum.cpp: the message says how to pass it).
enum GameMaterial { kBedrock = 1, kRock = 2, kNotAMaterial = 300 };
enum class ScopedMaterial { kRock = 2 };
static_assert(std::is_convertible_v<GameMaterial, Material> && Material(kRock) == Material(2));
static_assert(kConstantMaterial<kBedrock> && !std::is_convertible_v<ScopedMaterial, Material>);

std::int64_t refused_number(auto number) {
  try {
    const Material m(number);
    ADD_FAILURE() << "accepted " << int(m.value());
  } catch (const InvalidMaterial& e) {
    return e.number;
  }
  return 0;
}

TEST(Material, AnUnscopedEnumeratorIsItsNumber) {
  Landscape world({{0, 0}, {64, 64}}, kBedrock);
  world.fill(PolygonSet{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}}, kRock);
  EXPECT_EQ(world.material_at({5, 5}), kRock);
  EXPECT_EQ(world.material_at({50, 50}), kBedrock);
  EXPECT_EQ(refused_number(kNotAMaterial), 300);
}

TEST(Material, ANumberOutsideTheRangeIsRefusedWithTheNumber) {
  EXPECT_EQ(refused_number(256), 256);
  EXPECT_EQ(refused_number(-1), -1);
  EXPECT_EQ(refused_number(std::numeric_limits<std::int64_t>::min()),
            std::numeric_limits<std::int64_t>::min());
  // Larger than every int64: saturated, still refused (not wrapped to a small number).
  EXPECT_EQ(refused_number(std::numeric_limits<std::uint64_t>::max()),
            std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(refused_number(std::uint64_t{1} << 32), std::int64_t{1} << 32);
  EXPECT_EQ(refused_number(std::size_t{260}), 260);
  try {
    const Material m(300);
    FAIL() << int(m.value());
  } catch (const LandscapeError& e) {  // one of the landscape's errors
    EXPECT_STREQ(e.what(), "material 300 outside 0..255");
  }
}

TEST(Material, EveryNumberInRangeIsItself) {
  for (int n = 0; n < 256; ++n) EXPECT_EQ(Material(n).value(), n);
  EXPECT_EQ(Material(std::uint8_t{255}).value(), 255);
  EXPECT_EQ(to_string(Material(42)), "42");
  EXPECT_EQ(std::hash<Material>{}(Material(9)), 9u);
  const std::unordered_set<Material> set{1, 2, 2};
  EXPECT_EQ(set.size(), 2u);
}

// The two calls: before, fill(.., 260) filled material 4 and replace(.., 1, -1) wrote
// 255. Now each throws, and the world is exactly as it was.
TEST(Material, EditsWithANumberOutOfRangeThrowAndChangeNothing) {
  Landscape l({{0, 0}, {100, 100}}, 1);
  const PolygonSet square{{{10, 10}, {20, 10}, {20, 20}, {10, 20}}};
  const std::uint64_t before = l.state_hash();
  EXPECT_THROW(l.fill(square, 260), InvalidMaterial);
  EXPECT_THROW(l.replace(square, 1, -1), InvalidMaterial);
  EXPECT_THROW(l.fill_empty(square, 1000), InvalidMaterial);
  int computed = 255;
  ++computed;
  EXPECT_THROW(l.fill(square, computed), InvalidMaterial);
  EXPECT_THROW(Landscape({{0, 0}, {10, 10}}, 256), InvalidMaterial);
  EXPECT_EQ(l.state_hash(), before);
  EXPECT_EQ(l.twice_area(4), 0);
  EXPECT_EQ(l.twice_area(255), 0);
  EXPECT_EQ(l.twice_area(1), 2 * 100 * 100);
}

}  // namespace
}  // namespace edgeland::test
