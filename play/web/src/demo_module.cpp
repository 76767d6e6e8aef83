// The playground's demo module, demo.mjs (play/web/README.md): the pieces of demo/ that the page
// shows and the library does not have. The demo world's generator (demo/world.hpp) runs here and
// hands its rings to the page, which imports and applies each through the JavaScript package as
// demo::LandscapeEditor does natively, so the page's world is the package's and the same as the
// desktop's for the same box and seed. The palette and the material names are demo/palette.hpp's.
// No library code is compiled in: the generator and the palette are integer code over the
// library's header-only types (Point64, Material).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>
#include <string>

#include "edgeland/demo/editor.hpp"
#include "edgeland/demo/palette.hpp"
#include "edgeland/demo/world.hpp"
#include "edgeland/kernel/splitmix64.hpp"

namespace edgeland::demo {
namespace {

using emscripten::val;

// The package's Landscape method of each edit kind.
const char* method(log::LandscapeEditKind kind) {
  switch (kind) {
    case log::LandscapeEditKind::kCarve:
      return "carve";
    case log::LandscapeEditKind::kFill:
      return "fill";
    case log::LandscapeEditKind::kFillEmpty:
      return "fillEmpty";
    case log::LandscapeEditKind::kReplace:
      return "replace";
    case log::LandscapeEditKind::kRelabel:
      break;
  }
  return "relabel";
}

// The generator's edits as JavaScript objects {kind, material, from, ring: [[x, y], ...]}, in
// order (the ring as generated: the page imports it, OGC, as LandscapeEditor does).
class RingRecorder final : public DemoEditor {
 public:
  void edit(log::LandscapeEditKind kind, const Ring& ring, Material material,
            Material from) override {
    val points = val::array();
    for (const Point64& p : ring) {
      val xy = val::array();
      xy.call<void>("push", static_cast<double>(p.x), static_cast<double>(p.y));
      points.call<void>("push", xy);
    }
    val e = val::object();
    e.set("kind", std::string(method(kind)));
    e.set("material", material.value());
    e.set("from", from.value());
    e.set("ring", points);
    edits_.call<void>("push", e);
    ++count_;
  }
  // Every ring handed over (the page skips those of no area, as LandscapeEditor does).
  std::size_t edits() const noexcept override { return count_; }
  val recorded() const { return edits_; }

 private:
  val edits_ = val::array();
  std::size_t count_ = 0;
};

// The edits of demo_landscape(box, seed) with no actions: build_world's rings.
val world_edits(double x0, double y0, double x1, double y1, double seed) {
  const Box64 box{{static_cast<std::int64_t>(x0), static_cast<std::int64_t>(y0)},
                  {static_cast<std::int64_t>(x1), static_cast<std::int64_t>(y1)}};
  RingRecorder recorder;
  SplitMix64 random(static_cast<std::uint64_t>(seed));
  build_world(recorder, box, random);
  return recorder.recorded();
}

// A material's colour in pictures as 0xRRGGBB, so that the page and the PNGs agree.
int colour(int material) {
  const Rgb c = material_colour(Material(static_cast<std::uint8_t>(material & 0xff)));
  return c.r << 16 | c.g << 8 | c.b;
}

val names() {
  val out = val::array();
  for (const char* name : kMaterialNames) out.call<void>("push", std::string(name));
  return out;
}

int water() { return kWater.value(); }

}  // namespace

EMSCRIPTEN_BINDINGS(edgeland_demo) {
  emscripten::function("worldEdits", &world_edits);
  emscripten::function("materialColour", &colour);
  emscripten::function("materialNames", &names);
  emscripten::function("water", &water);
}

}  // namespace edgeland::demo
