#pragma once
// Inputs of the triangulation and convex-decomposition benchmarks (pieces_bench.cpp): every
// polygon of the demo world (realistic), and synthetic ones: combs with one-unit teeth, random
// stars, spirals keeping every lattice point, boxes with vertices along their sides. Fixed
// seeds; every polygon checked with validate() when built (not timed).
#include <string>
#include <vector>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::bench {

struct PiecesWorkload {
  std::string name;
  std::vector<Polygon> polygons;
  bool optimal = false;  // small enough for CGAL's O(n^4) optimal_convex_partition_2
};

// demo: the world of `edgeland demo` after `edits` edits (8192 x 8192, seed 1), every polygon;
// demo_small: those of at most 24 corners; comb_N, star_N, spiral_N, box_N: one polygon of
// about N vertices; stars_40: 200 random stars of 40 vertices.
std::vector<PiecesWorkload> pieces_workloads(std::size_t demo_edits);

// The polygon without its straight vertices (CGAL's partitions are given these).
Polygon corners_only(const Polygon& p);

}  // namespace edgeland::bench
