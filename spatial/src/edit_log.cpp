#include "edit_log.hpp"

#include <map>
#include <vector>

#include "edgeland/kernel/wkt_writer.hpp"
#include "edit_form.hpp"
#include "node.hpp"

namespace edgeland::detail {
namespace {

std::string number(Material m) { return std::to_string(m.value()); }

}  // namespace

std::string carve_line(const PolygonSet& shape) { return "carve " + to_wkt(shape) + "\n"; }
std::string fill_line(const PolygonSet& shape, Material m) {
  return "fill " + number(m) + " " + to_wkt(shape) + "\n";
}
std::string fill_empty_line(const PolygonSet& shape, Material m) {
  return "fill_empty " + number(m) + " " + to_wkt(shape) + "\n";
}
std::string replace_line(const PolygonSet& shape, Material from, Material to) {
  return "replace " + number(from) + " " + number(to) + " " + to_wkt(shape) + "\n";
}
std::string relabel_line(const PolygonSet& shape, const MaterialMap& map) {
  std::string line = "relabel ";
  for (std::size_t i = 0; i < kMaterialCount; ++i) {
    const Material from = static_cast<std::uint8_t>(i);
    if (map[from] != from) line += number(from) + " " + number(map[from]) + " ";
  }
  return line + to_wkt(shape) + "\n";
}
namespace {

// The line an edit alone would write (edit_form.hpp: its kind's, or relabel's for any map).
std::string edit_line(const Edit& e) {
  const PolygonSet& shape = e.shape.polygons();
  if (!has_its_form(e)) return relabel_line(shape, e.map);
  switch (e.kind) {
    case Edit::Kind::kCarve:
      return carve_line(shape);
    case Edit::Kind::kFill:
      return fill_line(shape, e.map[kEmpty]);
    case Edit::Kind::kFillEmpty:
      return fill_empty_line(shape, e.map[kEmpty]);
    case Edit::Kind::kReplace: {
      const auto [from, to] = replaced(e.map);
      return replace_line(shape, from, to);
    }
    case Edit::Kind::kRelabel:
      break;
  }
  return relabel_line(shape, e.map);
}

}  // namespace

std::string batch_line(std::span<const Edit> edits) {
  std::string line = "batch";
  for (std::size_t i = 0; i < edits.size(); ++i) {
    std::string one = edit_line(edits[i]);
    one.pop_back();  // its '\n'
    line.append(i == 0 ? " " : " | ").append(one);
  }
  return line + "\n";
}

std::string world_line(const Box64& w, Material fill) {
  std::string s = "world " + std::to_string(w.min.x) + " " + std::to_string(w.min.y) + " " +
                  std::to_string(w.max.x) + " " + std::to_string(w.max.y);
  // (Appended piece by piece: `" " + string` here set off g++ 12's false -Wrestrict.)
  if (fill != kEmpty) s.append(" ").append(number(fill));
  return s + "\n";
}

std::string state_log(const LandscapeState& s) {
  if (s.edits == 0) return world_line(s.world, s.initial_fill);
  // Polygons by material, in tree order and canonical order within a cell (as polygons_in).
  std::map<Material, PolygonSet> by_material;
  for_each_cell(s.root, [&](const NodePtr& cell) {
    for (std::size_t i = 0; i < cell->polygon_set().size(); ++i)
      by_material[cell->material(i)].push_back(cell->polygon_set()[i]);
  });
  std::string out = world_line(s.world, kEmpty);
  for (const auto& [m, set] : by_material) out += fill_line(set, m);
  return out;
}

std::string replay_log(const LandscapeState& s) { return s.logging ? log_text(s) : state_log(s); }

void append_log(LandscapeState& state, const std::string& line) {
  auto next = std::make_shared<LogLine>();
  next->prev = state.log;
  next->text = line;
  state.log = std::move(next);
}

std::string log_text(const LandscapeState& state) {
  std::vector<const LogLine*> lines;
  for (const LogLine* p = state.log.get(); p; p = p->prev.get()) lines.push_back(p);
  std::string out;
  for (auto it = lines.rbegin(); it != lines.rend(); ++it) out += (*it)->text;
  return out;
}

}  // namespace edgeland::detail
