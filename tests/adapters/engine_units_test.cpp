// The engine unit conversions (adapters/engine/include/edgeland/engine/units.hpp): the floating
// point a game sees, checked against values worked out by hand and against each other (a
// conversion and its inverse give back what went in).
#include <gtest/gtest.h>

#include <cmath>

#include "edgeland/engine/units.hpp"

namespace edgeland {
namespace {

TEST(EngineUnits, UnitVectorHasLengthOneAndKeepsTheDirection) {
  EXPECT_EQ(unit_vector({3, 4}), (EngineVec{0.6, 0.8}));
  EXPECT_EQ(unit_vector({0, -7}), (EngineVec{0, -1}));
  EXPECT_EQ(unit_vector({0, 0}), (EngineVec{}));  // no direction: stays (0, 0)
  // An edge normal as large as the coordinate bound allows: no overflow in the length.
  const EngineVec big = unit_vector({kCoordBound, -kCoordBound});
  EXPECT_NEAR(big.x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(big.y, -std::sqrt(0.5), 1e-15);
}

TEST(EngineUnits, LengthsConvertBothWaysByTheScale) {
  const EngineUnits units{{1000, -500}, 32};
  EXPECT_EQ(units.length_to_engine(64), 2.0);  // 64 units at 32 a metre: 2 m
  EXPECT_EQ(units.to_world_length(2.0), 64.0);
  for (const double length : {0.0, 1.0, 31.0, 4096.0, 1e9})
    EXPECT_DOUBLE_EQ(units.to_world_length(units.length_to_engine(length)), length);
}

TEST(EngineUnits, PointsGoAboutTheOriginAndComeBackExactly) {
  const EngineUnits units{{1000, -500}, 32};
  EXPECT_EQ(units.to_engine(Point64{1064, -468}), (EngineVec{2, 1}));
  for (const Point64 p : {Point64{1000, -500}, Point64{0, 0}, Point64{123457, -98765}})
    EXPECT_EQ(units.to_world(units.to_engine(p)), p);
  // A rational point with denominator 1 is the integer point.
  EXPECT_EQ(units.to_engine(RationalPoint{1064, -468, 1}), units.to_engine(Point64{1064, -468}));
}

TEST(EngineUnits, FractionsAndHitPointsAsDoubles) {
  EXPECT_EQ(to_double(Fraction{1, 4}), 0.25);
  EXPECT_EQ(to_double(RationalPoint{3, -5, 2}), (EngineVec{1.5, -2.5}));
}

}  // namespace
}  // namespace edgeland
