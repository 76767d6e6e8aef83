#pragma once
// Seeded shapes and positions of the landscape benchmarks (splitmix64, so every run and every
// rival sees the same edits). Vertices come from double trigonometry (this is bench/, not the
// library) and are rounded, as a game would make them.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "unit_draw.hpp"

namespace edgeland::bench {

// A regular n-gon around an integer centre, vertices rounded. Rounding moves vertices by more
// than a large n-gon's sagitta, so the result is slightly non-convex, but simple and with all n
// vertices; when rounding makes it invalid (small radii: repeated or crossing vertices) the
// convex hull of the rounded vertices instead.
Polygon ngon(Point64 centre, double radius, std::size_t sides);

// The vertex count a game would give a circle of this radius: one vertex per 8 units of
// circumference, at least 16, at most 512.
std::size_t game_sides(double radius);

// A stroke of the tunnel digger: the convex hull of the rounded `sides`-gons of ngon() at both
// ends. Not the kernel's capsule(), which takes its ends' corner count from circle_sides() (16 at
// radius 20) and its corners from integer trigonometry: the `dig` workload and its published
// figures (README.md, "Workloads") are strokes with 32-gon ends, and bitmap_world_check's
// shapes want corner counts of their own, so the bench keeps this shape under its own name.
Polygon ngon_stroke(Point64 a, Point64 b, double radius, std::size_t sides);

// `count` integer points uniform in the closed box.
std::vector<Point64> random_points(std::uint64_t seed, std::size_t count, const Box64& box);

// A random walk of `count` + 1 positions, `step` units apart (rounded), starting at the box's
// centre and turning by up to 10 degrees either way per step (a digger heads somewhere, so it
// mostly meets fresh rock); it turns back when it would leave the box.
std::vector<Point64> random_walk(std::uint64_t seed, std::size_t count, double step,
                                 const Box64& box);

// The box shrunk by `margin` on every side.
Box64 inset(const Box64& box, std::int64_t margin);

// A terrain's caves: `count` circles at random centres in the box, radii uniform in [24, 160],
// game_sides() vertices each.
std::vector<Polygon> caves(std::uint64_t seed, std::size_t count, const Box64& box);

// Each polygon as a one-member ValidSet (validated here, before any clock starts).
std::vector<ValidSet> as_shapes(const std::vector<Polygon>& polygons);

// The edit workloads of the landscape and game benchmarks (landscape_edits.cpp,
// game_edits.cpp), so both measure the same edits:
//   explosions: `count` 32-gons of radius 40 at random centres in the world box;
//   digger strokes: `count` ngon_strokes of radius 20 (32-gon ends) along a random walk, 10 units
//   per step, inside the world box less a 64-unit margin.
inline constexpr std::uint64_t kCarveSeed = 0xCA4'F1A6;  // the carved explosions
inline constexpr std::uint64_t kFillSeed = 0xF111'0002;  // the filled ones (other centres)
inline constexpr std::uint64_t kDigSeed = 0xD16'6E2;
std::vector<ValidSet> explosions(std::uint64_t seed, std::size_t count, const Box64& world);
std::vector<ValidSet> digger_strokes(std::uint64_t seed, std::size_t count, const Box64& world);

}  // namespace edgeland::bench
