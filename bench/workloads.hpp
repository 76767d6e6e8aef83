#pragma once
// Seeded, deterministic inputs for the benchmarks: the same polygons for every peer, every run.
// All coordinates are integers well inside the library's range (|c| <= ~1.2e7 << 2^31).
// The generators use double trigonometry (this is bench/, not the library): inputs may differ
// in the last unit between C libraries, never between peers of one run. Every generated
// operand is checked with edgeland::validate before it is used.
#include <cstddef>
#include <cstdint>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::bench {

struct Operands {
  PolygonSet subject;
  PolygonSet clip;
};

// Two star-shaped polygons of n vertices each whose radius varies smoothly with the angle
// (two low harmonics), centres and phases offset: their boundaries cross a few dozen times.
Operands smooth_stars(std::size_t n);

// Two star-shaped polygons of n vertices each with independent random radii in [0.3R, R]
// around centres 0.15R apart: long spikes of one cross many spikes of the other, so the
// number of crossings grows like n^2.
Operands spiky_stars(std::size_t n);

// n unit squares (side 1000) on the black cells of a checkerboard (touching at corners) and
// the same n squares shifted by (500, 250).
Operands checkerboard(std::size_t n);

// The carving workload: an 8192 x 8192 square and `count` 32-gons of radius 40 with random
// integer centres in the square, each one a separate operand.
struct Carving {
  Polygon square;
  PolygonSet holes;
};
Carving carving(std::size_t count);

// Throws std::logic_error naming the workload if `set` is not a valid polygon set.
void require_valid(const PolygonSet& set, const char* what);

// The point at distance r and `angle` (radians) from (cx, cy), rounded to the nearest integer
// (halves away from zero): the workloads' one use of floating point, in building inputs.
Point64 polar(double cx, double cy, double r, double angle);

}  // namespace edgeland::bench
