#pragma once
// The point grids the exhaustive checks enumerate.
#include <cstdint>
#include <vector>

#include "edgeland/kernel/point.hpp"

namespace edgeland::exhaustive {

// The n x n grid {origin + i*step} in both axes, row by row.
inline std::vector<Point64> grid(int n, std::int64_t origin = 0, std::int64_t step = 1) {
  std::vector<Point64> points;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) points.push_back({origin + x * step, origin + y * step});
  }
  return points;
}

// An n x n grid stretched over the whole coordinate range [-kCoordBound, kCoordBound]
// (the abscissas are -B + round_down(i * 2B / (n-1)), so the spacing differs by one unit
// here and there: nearly-collinear triples at the extremes of the range).
inline std::vector<Point64> full_range_grid(int n) {
  std::vector<std::int64_t> c;
  for (int i = 0; i < n; ++i) c.push_back(-kCoordBound + (2 * kCoordBound * i) / (n - 1));
  std::vector<Point64> points;
  for (std::int64_t y : c) {
    for (std::int64_t x : c) points.push_back({x, y});
  }
  return points;
}

}  // namespace edgeland::exhaustive
