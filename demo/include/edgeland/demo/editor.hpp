#pragma once
// The landscape demo's hand on its world: turns each generated ring into a valid shape and
// applies one edit with it, counting the edits.
#include <cstddef>

#include "edgeland/io/landscape_log.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::demo {

// The demo's materials; material_palette.hpp colours them.
inline constexpr Material kBedrock = 1;
inline constexpr Material kRock = 2;
inline constexpr Material kDirt = 3;
inline constexpr Material kOre = 4;
inline constexpr Material kWater = 5;
inline constexpr Material kSand = 6;
inline constexpr Material kGrass = 7;
inline constexpr Material kCrystal = 8;

class DemoEditor {
 public:
  explicit DemoEditor(Landscape& landscape) : landscape_(landscape) {}

  // Imports `ring` as an OGC polygon (clip.hpp import_polygons: integer rounding of the
  // trigonometry may leave a ring that is not strictly simple) and applies the edit of `kind`
  // (log::apply_edit's arguments); a ring of no area is skipped. Throws what the landscape's
  // edits throw.
  void edit(log::LandscapeEditKind kind, const Ring& ring, Material material = kEmpty,
            Material from = kEmpty);

  void carve(const Ring& ring) { edit(log::LandscapeEditKind::kCarve, ring); }
  void fill(const Ring& ring, Material m) { edit(log::LandscapeEditKind::kFill, ring, m); }
  void fill_empty(const Ring& ring, Material m) {
    edit(log::LandscapeEditKind::kFillEmpty, ring, m);
  }
  void replace(const Ring& ring, Material from, Material to) {
    edit(log::LandscapeEditKind::kReplace, ring, to, from);
  }

  std::size_t edits() const noexcept { return edits_; }

 private:
  Landscape& landscape_;
  std::size_t edits_ = 0;
};

}  // namespace edgeland::demo
