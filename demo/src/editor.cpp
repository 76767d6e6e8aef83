#include "edgeland/demo/editor.hpp"

#include "edgeland/clip/clip.hpp"

namespace edgeland::demo {

void DemoEditor::edit(log::LandscapeEditKind kind, const Ring& ring, Material material,
                      Material from) {
  const ClipOptions options{.checked = landscape_.checked()};
  const PolygonSet shape = import_polygons({{ring}}, options).polygons;
  if (shape.empty()) return;
  log::apply_edit(landscape_, kind, shape, material, from);
  ++edits_;
}

}  // namespace edgeland::demo
