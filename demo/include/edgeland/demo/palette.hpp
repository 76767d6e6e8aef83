#pragma once
// The colours and names of the materials in pictures (`--png`, `render`, the front ends): a fixed
// table for the first materials, chosen for the demo's layers, and a hash of the number for the
// rest, so that every material always has the same colour in every picture.
#include <array>
#include <cstdint>

#include "edgeland/kernel/splitmix64.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::demo {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

// Material 0 (empty space) is the dark background; every solid material is at least three
// times as bright as it, so that bedrock (1) reads clearly against empty space.
inline constexpr std::array<Rgb, 11> kNamedMaterialColours{{
    {16, 18, 24},     // 0 empty space
    {112, 100, 136},  // 1 bedrock: slate
    {156, 158, 170},  // 2 rock
    {176, 116, 60},   // 3 dirt
    {255, 206, 40},   // 4 ore
    {60, 140, 255},   // 5 water
    {244, 224, 150},  // 6 sand
    {96, 200, 70},    // 7 grass
    {200, 112, 255},  // 8 crystal
    {255, 96, 32},    // 9 lava
    {190, 240, 255},  // 10 ice
}};

// The names of the materials the demos use (cli/demo_editor.hpp), for legends.
inline constexpr std::array<const char*, 11> kMaterialNames{
    "empty", "bedrock", "rock", "dirt", "ore", "water", "sand", "grass", "crystal", "lava", "ice"};

inline const char* material_name(Material m) {
  return m.value() < kMaterialNames.size() ? kMaterialNames[m.value()] : "";
}

inline Rgb material_colour(Material m) {
  if (m.value() < kNamedMaterialColours.size()) return kNamedMaterialColours[m.value()];
  // The splitmix64 mix spreads neighbouring numbers over the colour cube; each channel
  // is kept in 80..239 so that no material is mistaken for the dark background.
  const std::uint64_t z = mix64(m.value() + kSplitMix64Gamma);
  const auto channel = [&](int shift) {
    return static_cast<std::uint8_t>(80 + ((z >> shift) & 0xff) * 160 / 256);
  };
  return {channel(0), channel(8), channel(16)};
}

}  // namespace edgeland::demo
