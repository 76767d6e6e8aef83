#include "log_line.hpp"

#include <map>
#include <vector>

#include "edgeland/kernel/wkt_writer.hpp"
#include "landscape_access.hpp"

namespace edgeland::detail {
namespace {

std::string number(Material m) { return std::to_string(static_cast<unsigned>(m)); }

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
std::string world_line(const Box64& w, Material fill) {
  std::string s = "world " + std::to_string(w.min.x) + " " + std::to_string(w.min.y) + " " +
                  std::to_string(w.max.x) + " " + std::to_string(w.max.y);
  // (Appended piece by piece: `" " + string` here set off g++ 12's false -Wrestrict.)
  if (fill != kEmpty) s.append(" ").append(number(fill));
  return s + "\n";
}

std::string state_log(const Landscape& l) {
  if (LandscapeAccess::edits(l) == 0)
    return world_line(l.world(), LandscapeAccess::initial_fill(l));
  std::map<Material, PolygonSet> by_material;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    by_material[v.material].push_back(*v.polygon);
    return true;
  });
  std::string out = world_line(l.world(), kEmpty);
  for (const auto& [m, set] : by_material) out += fill_line(set, m);
  return out;
}

std::string replay_log(const Landscape& l) { return l.logging() ? log_text(l) : state_log(l); }

void append_log(Landscape& l, const std::string& line) {
  auto next = std::make_shared<Landscape::LogLine>();
  next->prev = LandscapeAccess::log(l);
  next->text = line;
  LandscapeAccess::set_log(l, std::move(next));
}

std::string log_text(const Landscape& l) {
  std::vector<const Landscape::LogLine*> lines;
  for (const Landscape::LogLine* p = LandscapeAccess::log(l).get(); p; p = p->prev.get())
    lines.push_back(p);
  std::string out;
  for (auto it = lines.rbegin(); it != lines.rend(); ++it) out += (*it)->text;
  return out;
}

}  // namespace edgeland::detail
