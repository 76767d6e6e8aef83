#include "changes.hpp"

#include <algorithm>

#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/scratch.hpp"

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

// One polygon of a changed cell, found by its id.
struct Seen {
  PolygonId id;
  const Node* cell;
  std::size_t index;
};

// Every polygon of `cells`, by ascending id (ids are unique within one tree).
void ids_of(const std::vector<NodePtr>& cells, ScratchVector<Seen>& out) {
  out.clear();
  for (const NodePtr& c : cells)
    for (std::size_t i = 0; i < c->ids.size(); ++i) out.push_back({c->ids[i], c.get(), i});
  std::sort(out.begin(), out.end(), [](const Seen& l, const Seen& r) { return l.id < r.id; });
}

// Twice the area change per material, few materials a change: a flat list, sorted at the end.
class AreaDelta {
 public:
  void add(Material m, const Int128& a) {
    const auto at =
        std::find_if(sums_.begin(), sums_.end(), [m](const auto& s) { return s.first == m; });
    if (at == sums_.end())
      sums_.emplace_back(m, a);
    else
      at->second += a;
  }
  // The nonzero sums by ascending material.
  std::vector<std::pair<Material, Int128>> nonzero() {
    std::erase_if(sums_, [](const auto& s) { return s.second == 0; });
    std::sort(sums_.begin(), sums_.end(),
              [](const auto& l, const auto& r) { return l.first < r.first; });
    return std::move(sums_);
  }

 private:
  std::vector<std::pair<Material, Int128>> sums_;
};

void note_removed(const Seen& seen, ChangeSet& out, AreaDelta& delta) {
  out.removed.push_back(seen.id);
  const Int128 a = twice_signed_area(seen.cell->polygon_set()[seen.index]);
  delta.add(seen.cell->material(seen.index), -a);
  delta.add(kEmpty, a);
}

void note_added(const Seen& seen, ChangeSet& out, AreaDelta& delta) {
  const Material m = seen.cell->material(seen.index);
  const Polygon& p = seen.cell->polygon_set()[seen.index];
  out.added.push_back({seen.id, m, p, seen.cell->box});
  const Int128 a = twice_signed_area(p);
  delta.add(m, a);
  delta.add(kEmpty, -a);
}

}  // namespace

Changes diff(const NodePtr& old_root, const NodePtr& new_root) {
  Changes out;
  walk(old_root, new_root, out);
  return out;
}

ChangeSet change_set(const Changes& changes) {
  ScratchVector<Seen> before, after;  // scratch: the change set itself is all that is allocated
  ids_of(changes.old_cells, before);
  ids_of(changes.new_cells, after);
  ChangeSet out;
  AreaDelta delta;
  // Both lists ascend by id: one merge finds the ids only one side has, in ascending order.
  std::size_t i = 0, j = 0;
  while (i < before.size() || j < after.size()) {
    if (j == after.size() || (i < before.size() && before[i].id < after[j].id)) {
      note_removed(before[i++], out, delta);
    } else if (i == before.size() || after[j].id < before[i].id) {
      note_added(after[j++], out, delta);
    } else {
      ++i;
      ++j;
    }
  }
  out.twice_area_delta = delta.nonzero();
  out.cells.reserve(changes.new_cells.size());
  for (const NodePtr& c : changes.new_cells) out.cells.push_back(c->box);
  return out;
}

}  // namespace edgeland::detail
