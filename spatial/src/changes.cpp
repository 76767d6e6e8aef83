#include "changes.hpp"

#include <algorithm>
#include <map>

#include "edgeland/kernel/area.hpp"

namespace edgeland::detail {
namespace {

void collect(const NodePtr& node, std::vector<NodePtr>& cells, std::vector<NodePtr>* inner) {
  if (node->is_stub()) return;  // an unloaded region: nothing of it is seen to come or go
  if (node->is_cell()) {
    cells.push_back(node);
    return;
  }
  if (inner) inner->push_back(node);
  for (std::uint32_t i = 0; i < node->child_count; ++i) collect(node->children[i], cells, inner);
}

void walk(const NodePtr& o, const NodePtr& n, Changes& out) {
  if (o == n) return;
  // Two inner nodes of one box always have the same children's boxes (split_boxes), so the
  // child counts differ in no test; compared anyway, so a tree of another shape would be told
  // apart by its cells rather than walked child by child.
  if (!o->is_cell() && !n->is_cell() && o->child_count == n->child_count) {
    out.new_inner.push_back(n);
    for (std::uint32_t i = 0; i < o->child_count; ++i) walk(o->children[i], n->children[i], out);
    return;
  }
  collect(o, out.old_cells, nullptr);
  collect(n, out.new_cells, &out.new_inner);
}

struct Seen {
  const Node* cell;
  std::size_t index;
};

std::map<PolygonId, Seen> ids_of(const std::vector<NodePtr>& cells) {
  std::map<PolygonId, Seen> out;
  for (const NodePtr& c : cells)
    for (std::size_t i = 0; i < c->ids.size(); ++i) out[c->ids[i]] = {c.get(), i};
  return out;
}

}  // namespace

Changes diff(const NodePtr& old_root, const NodePtr& new_root) {
  Changes out;
  walk(old_root, new_root, out);
  return out;
}

ChangeSet change_set(const Changes& changes) {
  const std::map<PolygonId, Seen> before = ids_of(changes.old_cells);
  const std::map<PolygonId, Seen> after = ids_of(changes.new_cells);
  std::map<Material, Int128> delta;
  ChangeSet out;
  for (const auto& [id, seen] : before) {
    if (after.count(id)) continue;
    out.removed.push_back(id);
    const auto m = seen.cell->material(seen.index);
    const Int128 a = twice_signed_area(seen.cell->polygon_set()[seen.index]);
    delta[m] -= a;
    delta[kEmpty] += a;
  }
  for (const auto& [id, seen] : after) {
    if (before.count(id)) continue;
    const auto m = seen.cell->material(seen.index);
    const Polygon& p = seen.cell->polygon_set()[seen.index];
    out.added.push_back({id, m, p, seen.cell->box});
    const Int128 a = twice_signed_area(p);
    delta[m] += a;
    delta[kEmpty] -= a;
  }
  for (const auto& [m, d] : delta)
    if (d != 0) out.twice_area_delta.emplace_back(m, d);
  for (const NodePtr& c : changes.new_cells) out.cells.push_back(c->box);
  return out;
}

}  // namespace edgeland::detail
