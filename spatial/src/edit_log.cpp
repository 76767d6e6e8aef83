#include "edit_log.hpp"

#include <map>
#include <vector>

#include "edgeland/spatial/log_format.hpp"
#include "node.hpp"

namespace edgeland::detail {
std::string state_log(const LandscapeState& s) {
  if (s.edits == 0) return log::world_line(s.world, s.initial_fill);
  // Polygons by material, in tree order and canonical order within a cell (as polygons_in).
  std::map<Material, PolygonSet> by_material;
  for_each_cell(s.root, [&](const NodePtr& cell) {
    for (std::size_t i = 0; i < cell->polygon_set().size(); ++i)
      by_material[cell->material(i)].push_back(cell->polygon_set()[i]);
  });
  std::string out = log::world_line(s.world, kEmpty);
  for (const auto& [m, set] : by_material)
    out += log::edit_line(log::LandscapeEditKind::kFill, set, m);
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
