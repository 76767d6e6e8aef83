#pragma once
// The shapes of the landscape demo, as rings with integer vertices from the integer
// trigonometry table: rough n-gons (explosions, caves, pools) and regions under or along wavy
// lines (layers and bands). A step of a tunnel or a vein is the kernel's capsule()
// (kernel/shapes.hpp).
#include <array>
#include <cstdint>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/splitmix64.hpp"

namespace edgeland::demo {

// An n-gon of radius r around c whose vertices lie at r * (100 - roughness .. 100) / 100 from
// c, each drawn from `random`: a star-shaped, counter-clockwise ring.
Ring rough_ngon(Point64 c, std::int64_t r, int n, int roughness, SplitMix64& random);

// y = base + sum of amplitude * sin(cycles turns across the world + phase): a wavy line over
// the world's width.
struct WavyLine {
  std::int64_t base = 0;
  std::array<std::int64_t, 3> amplitude{};
  std::array<int, 3> cycles{};
  std::array<int, 3> phase{};  // 1/256 turns

  std::int64_t y_at(std::int64_t x, const Box64& world) const;
};

// A line around `base` with three random waves of at most `amplitude`, halving each time.
WavyLine random_wavy_line(std::int64_t base, std::int64_t amplitude, SplitMix64& random);

// The region of the world's width between the world's bottom (and a little below) and the
// line, sampled every `step` units.
Ring region_below(const WavyLine& line, const Box64& world, std::int64_t step);

// The band between line + offset and line + offset + thickness (thickness > 0).
Ring band_along(const WavyLine& line, std::int64_t offset, std::int64_t thickness,
                const Box64& world, std::int64_t step);

}  // namespace edgeland::demo
