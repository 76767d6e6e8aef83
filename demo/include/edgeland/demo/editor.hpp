#pragma once
// The demo's hand on its world: the generator (world.hpp, actions.hpp) makes rings and says
// what each does (carve, fill, fill_empty, replace); an editor takes them. LandscapeEditor
// imports each ring and applies it to a landscape; the browser playground's demo module hands
// them to the JavaScript package, which imports and applies them the same way (play/web).
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
  virtual ~DemoEditor() = default;

  // One generated ring as one edit of `kind` (log::apply_edit's arguments: `material` is fill's
  // and fill_empty's material and replace's TO, `from` replace's FROM). The ring may not be
  // strictly simple (integer rounding of the trigonometry): it is read as an OGC polygon.
  virtual void edit(log::LandscapeEditKind kind, const Ring& ring, Material material = kEmpty,
                    Material from = kEmpty) = 0;
  // The edits made so far (the players' actions run until they have made theirs).
  virtual std::size_t edits() const noexcept = 0;

  void carve(const Ring& ring) { edit(log::LandscapeEditKind::kCarve, ring); }
  void fill(const Ring& ring, Material m) { edit(log::LandscapeEditKind::kFill, ring, m); }
  void fill_empty(const Ring& ring, Material m) {
    edit(log::LandscapeEditKind::kFillEmpty, ring, m);
  }
  void replace(const Ring& ring, Material from, Material to) {
    edit(log::LandscapeEditKind::kReplace, ring, to, from);
  }
};

// Each ring imported as an OGC polygon (clip.hpp import_polygons) and applied to the landscape
// as one edit; a ring of no area is skipped. Counts the edits.
class LandscapeEditor final : public DemoEditor {
 public:
  explicit LandscapeEditor(Landscape& landscape) : landscape_(landscape) {}

  // Throws what the landscape's edits throw.
  void edit(log::LandscapeEditKind kind, const Ring& ring, Material material = kEmpty,
            Material from = kEmpty) override;

  std::size_t edits() const noexcept override { return edits_; }

 private:
  Landscape& landscape_;
  std::size_t edits_ = 0;
};

}  // namespace edgeland::demo
