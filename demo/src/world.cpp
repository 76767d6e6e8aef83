#include "edgeland/demo/world.hpp"

namespace edgeland::demo {
namespace {

// Waves are sampled every kStep units: 129 points across an 8192 world.
constexpr std::int64_t kStep = 64;

std::int64_t height(const Box64& world, std::int64_t per_mille) {
  return world.min.y + (world.max.y - world.min.y) * per_mille / 1000;
}

std::int64_t scaled(const Box64& world, std::int64_t per_mille) {
  return (world.max.y - world.min.y) * per_mille / 1000;
}

// Dirt under the surface, rock under that, bedrock at the bottom: each fill covers the one
// before where it reaches.
Terrain lay_layers(DemoEditor& editor, const Box64& world, SplitMix64& random) {
  Terrain t;
  t.surface = random_wavy_line(height(world, 690), scaled(world, 36), random);
  t.rock_top = random_wavy_line(height(world, 570), scaled(world, 40), random);
  const WavyLine bedrock = random_wavy_line(height(world, 80), scaled(world, 16), random);
  editor.fill(region_below(t.surface, world, kStep), kDirt);
  editor.fill(region_below(t.rock_top, world, kStep), kRock);
  editor.fill(region_below(bedrock, world, kStep), kBedrock);
  // A grass skin: the top of the dirt along the surface.
  editor.replace(band_along(t.surface, -scaled(world, 6), scaled(world, 12), world, kStep), kDirt,
                 kGrass);
  return t;
}

// Per mille of the world's height: [lo, hi] for each random draw of a band.
struct BandRanges {
  std::int64_t base_lo, base_hi, amplitude_lo, amplitude_hi, thickness_lo, thickness_hi;
};

// One thin wavy band turning `from` into `to` where it crosses it.
void lay_band(DemoEditor& editor, const Box64& world, SplitMix64& random, const BandRanges& r,
              Material from, Material to) {
  // Each random number in its own statement: argument evaluation order is unspecified.
  const std::int64_t base = height(world, random.between(r.base_lo, r.base_hi));
  const std::int64_t amplitude = scaled(world, random.between(r.amplitude_lo, r.amplitude_hi));
  const WavyLine line = random_wavy_line(base, amplitude, random);
  const std::int64_t thickness = scaled(world, random.between(r.thickness_lo, r.thickness_hi));
  editor.replace(band_along(line, 0, thickness, world, kStep), from, to);
}

// Thin wavy bands turn rock into ore (veins) and dirt into sand (pockets) where they cross it.
void lay_bands(DemoEditor& editor, const Box64& world, SplitMix64& random) {
  for (int i = 0; i < 5; ++i)
    lay_band(editor, world, random, {140, 540, 10, 30, 3, 8}, kRock, kOre);
  for (int i = 0; i < 2; ++i)
    lay_band(editor, world, random, {600, 660, 10, 20, 6, 12}, kDirt, kSand);
}

// Caves in the rock, the lower part of every third one flooded (only its empty space fills).
void carve_caves(DemoEditor& editor, const Box64& world, SplitMix64& random) {
  for (int i = 0; i < 28; ++i) {
    const Point64 c{world.min.x + (world.max.x - world.min.x) * random.between(30, 970) / 1000,
                    height(world, random.between(130, 520))};
    const std::int64_t r = scaled(world, random.between(12, 45));
    const auto n = static_cast<int>(random.between(14, 28));
    editor.carve(rough_ngon(c, r, n, 35, random));
    if (i % 3 == 0) {
      const Ring pool{
          {c.x - r, c.y - r}, {c.x + r, c.y - r}, {c.x + r, c.y - r / 3}, {c.x - r, c.y - r / 3}};
      editor.fill_empty(pool, kWater);
    }
    if (i % 7 == 3) {
      editor.replace(rough_ngon(c, r + scaled(world, 4), 20, 10, random), kRock, kCrystal);
    }
  }
}

}  // namespace

Terrain build_world(DemoEditor& editor, const Box64& world, SplitMix64& random) {
  const Terrain terrain = lay_layers(editor, world, random);
  lay_bands(editor, world, random);
  carve_caves(editor, world, random);
  return terrain;
}

}  // namespace edgeland::demo
