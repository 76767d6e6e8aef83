// The lines of the landscape edit log (log_format.hpp).
#include "edgeland/spatial/log_format.hpp"

#include "edgeland/kernel/wkt_writer.hpp"
#include "edit_form.hpp"

namespace edgeland::log {
namespace {

std::string number(Material m) { return std::to_string(m.value()); }

// The keyword and a space.
std::string start(LandscapeEditKind kind) {
  return std::string(edit_keyword(kind).word).append(" ");
}

}  // namespace

std::string world_line(const Box64& w, Material fill) {
  std::string s = std::string(kWorldKeyword) + " " + std::to_string(w.min.x) + " " +
                  std::to_string(w.min.y) + " " + std::to_string(w.max.x) + " " +
                  std::to_string(w.max.y);
  // (Appended piece by piece: `" " + string` here set off g++ 12's false -Wrestrict.)
  if (fill != kEmpty) s.append(" ").append(number(fill));
  return s + "\n";
}

std::string edit_line(LandscapeEditKind kind, const PolygonSet& shape, Material material,
                      Material from) {
  std::string line = start(kind);
  if (kind == LandscapeEditKind::kReplace || kind == LandscapeEditKind::kRelabel)
    line += number(from) + " ";
  if (kind != LandscapeEditKind::kCarve) line += number(material) + " ";
  return line + to_wkt(shape) + "\n";
}

std::string relabel_line(const PolygonSet& shape, const MaterialMap& map) {
  std::string line = start(LandscapeEditKind::kRelabel);
  for (std::size_t i = 0; i < kMaterialCount; ++i) {
    const Material from = static_cast<std::uint8_t>(i);
    if (map[from] != from) line += number(from) + " " + number(map[from]) + " ";
  }
  return line + to_wkt(shape) + "\n";
}

std::string edit_line(const Edit& edit) {
  const PolygonSet& shape = edit.shape.polygons();
  if (!detail::has_its_form(edit) || edit.kind == LandscapeEditKind::kRelabel)
    return relabel_line(shape, edit.map);
  const auto [from, to] = detail::replaced(edit.map);
  const Material material = edit.kind == LandscapeEditKind::kReplace ? to : edit.map[kEmpty];
  return edit_line(edit.kind, shape, material, from);
}

std::string batch_line(std::span<const Edit> edits) {
  std::string line(kBatchKeyword);
  for (std::size_t i = 0; i < edits.size(); ++i) {
    if (i > 0) (line += ' ') += kBatchSeparator;
    std::string one = edit_line(edits[i]);
    one.pop_back();  // its '\n'
    (line += ' ') += one;
  }
  return line + "\n";
}

}  // namespace edgeland::log
