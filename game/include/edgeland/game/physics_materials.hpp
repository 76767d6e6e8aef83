#pragma once
// Which materials a physics engine collides with, and which never fall.
#include <array>

#include "edgeland/spatial/landscape.hpp"

namespace edgeland {

// solid: the material collides (rock, dirt; not water or gas). anchored: the material never
// falls (bedrock): a piece of solid material connected to an anchored one is held in place.
// Material 0 (empty space) is never solid, whatever the table says. Defaults: every non-zero
// material solid, none anchored. The tables are indexed by Material::value().
struct PhysicsMaterials {
  std::array<bool, kMaterialCount> solid;
  std::array<bool, kMaterialCount> anchored{};

  PhysicsMaterials() { solid.fill(true); }
  PhysicsMaterials& set_solid(Material m, bool on = true) {
    solid[m.value()] = on;
    return *this;
  }
  PhysicsMaterials& set_anchored(Material m, bool on = true) {
    anchored[m.value()] = on;
    return *this;
  }
  bool is_solid(Material m) const noexcept { return m != kEmpty && solid[m.value()]; }
  bool is_anchored(Material m) const noexcept { return is_solid(m) && anchored[m.value()]; }
  friend bool operator==(const PhysicsMaterials&, const PhysicsMaterials&) = default;
};

}  // namespace edgeland
