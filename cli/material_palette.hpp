#pragma once
// The colours of the materials in pictures (`--png`): a fixed table for the first materials,
// chosen for the demo's layers, and a hash of the number for the rest, so that every
// material always has the same colour in every picture.
#include <array>
#include <cstdint>

#include "edgeland/spatial/landscape.hpp"
#include "splitmix64.hpp"

namespace edgeland::cli {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

// Material 0 (empty space) is the dark background.
inline constexpr std::array<Rgb, 11> kNamedMaterialColours{{
    {18, 20, 26},     // 0 empty space
    {58, 56, 62},     // 1 bedrock
    {124, 124, 132},  // 2 rock
    {140, 94, 52},    // 3 dirt
    {242, 190, 40},   // 4 ore
    {52, 112, 216},   // 5 water
    {228, 208, 140},  // 6 sand
    {78, 164, 64},    // 7 grass
    {168, 88, 216},   // 8 crystal
    {228, 76, 28},    // 9 lava
    {176, 228, 240},  // 10 ice
}};

inline Rgb material_colour(Material m) {
  if (m.value() < kNamedMaterialColours.size()) return kNamedMaterialColours[m.value()];
  // The splitmix64 mix spreads neighbouring numbers over the colour cube; each channel
  // is kept in 80..239 so that no material is mistaken for the dark background.
  const std::uint64_t z = mix64(m.value() + 0x9e3779b97f4a7c15ull);
  const auto channel = [&](int shift) {
    return static_cast<std::uint8_t>(80 + ((z >> shift) & 0xff) * 160 / 256);
  };
  return {channel(0), channel(8), channel(16)};
}

}  // namespace edgeland::cli
