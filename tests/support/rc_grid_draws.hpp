#pragma once
// RapidCheck draws for properties over small grids (the validate() tests, the validating
// clip's tests): integers uniform over a range whatever RapidCheck's current size, grid
// points, and triangles on a grid.
#include <rapidcheck.h>

#include <cstdint>
#include <utility>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland::testing {

// Uniform over [lo, hi) whatever RapidCheck's current size (inRange alone shrinks the range
// with the size, which would make the first cases all zeros); shrinks toward lo.
struct RcDraw {
  std::int64_t operator()(std::int64_t lo, std::int64_t hi) const {
    return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange<std::int64_t>(lo, hi));
  }
};

// A point of the grid [0, size]^2.
inline Point64 grid_point(std::int64_t size) {
  return {RcDraw{}(0, size + 1), RcDraw{}(0, size + 1)};
}

// A triangle on the grid [0, size]^2, turned counter-clockwise if it has area, left flat
// otherwise.
inline Polygon grid_triangle(std::int64_t size) {
  Polygon t{grid_point(size), grid_point(size), grid_point(size)};
  if (orientation(t[0], t[1], t[2]) == Orientation::kClockwise) std::swap(t[1], t[2]);
  return t;
}

}  // namespace edgeland::testing
