#include "island_summary.hpp"

#include <algorithm>

#include "edgeland/kernel/scratch.hpp"
#include "edgeland/kernel/splitmix64.hpp"
#include "solid_boundary.hpp"
#include "union_find.hpp"

namespace edgeland::game_detail {
namespace {

using detail::ScratchVector;

// splitmix64's first output from state x: spreads ids so that sums of different sets rarely
// collide.
std::uint64_t mixed(std::uint64_t x) { return mix64(x + kSplitMix64Gamma); }

// Ports of one group that abut along a side become one: a port overlaps another over a positive
// length exactly when one of its parts does, so matching gives the same unions, and a node's
// sides keep one port per run of solid instead of one per cell along them. Compacts the sides in
// place, in order.
void join_abutting(Summary& s) {
  std::size_t kept = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t begin = s.side_begin[k], end = s.side_begin[k + 1];
    s.side_begin[k] = static_cast<std::uint32_t>(kept);
    for (std::size_t i = begin; i < end; ++i) {
      const Port p = s.ports[i];
      if (kept > s.side_begin[k] && s.ports[kept - 1].hi == p.lo &&
          s.ports[kept - 1].group == p.group)
        s.ports[kept - 1].hi = p.hi;
      else
        s.ports[kept++] = p;
    }
  }
  s.side_begin[4] = static_cast<std::uint32_t>(kept);
  s.ports.resize(kept);
}

// Groups 0..n-1 united into classes; keeps the classes that still have ports (renumbered in
// order of first appearance along the sides) and closes the others. `out.ports` holds the ports
// (groups numbered 0..n-1) on entry; its other lists are written anew, reusing their storage.
void finish(std::span<Group> groups, ScratchUnionFind& uf, Summary& out) {
  for (std::uint32_t g = 0; g < groups.size(); ++g) {
    const std::uint32_t root = uf.find(g);
    if (root == g) continue;
    groups[root].anchored = groups[root].anchored || groups[g].anchored;
    groups[root].key.add(groups[g].key);
  }
  out.groups.clear();
  out.closed.clear();
  ScratchVector<std::uint32_t> renumbered;
  renumbered.assign(groups.size(), kNotSolid);
  for (Port& p : out.ports) {  // along the sides in order: the order of first appearance
    std::uint32_t& n = renumbered[uf.find(p.group)];
    if (n == kNotSolid) {
      n = static_cast<std::uint32_t>(out.groups.size());
      out.groups.push_back(groups[uf.find(p.group)]);
    }
    p.group = n;
  }
  join_abutting(out);
  for (std::uint32_t g = 0; g < groups.size(); ++g) {
    const Group& root = groups[g];
    if (uf.find(g) != g || renumbered[g] != kNotSolid || root.anchored) continue;
    out.closed.push_back({root.key, root.representative, root.representative_cell});
  }
}

// Unites the groups of two port lists facing each other across a line wherever they overlap
// over a positive length (both ascending, disjoint within each).
void match(std::span<const Port> a, std::uint32_t a_offset, std::span<const Port> b,
           std::uint32_t b_offset, ScratchUnionFind& uf, std::size_t& matched) {
  matched += a.size() + b.size();
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::min(a[i].hi, b[j].hi) > std::max(a[i].lo, b[j].lo))
      uf.unite(a[i].group + a_offset, b[j].group + b_offset);
    if (a[i].hi < b[j].hi)
      ++i;
    else
      ++j;
  }
}

constexpr std::size_t side_index(Side s) { return static_cast<std::size_t>(s); }

}  // namespace

IslandKey IslandKey::of(PolygonId id) { return {id, 1, id, mixed(id)}; }

void IslandKey::add(const IslandKey& o) {
  min_id = std::min(min_id, o.min_id);
  count += o.count;
  sum += o.sum;
  mix += o.mix;
}

void leaf_summary(const CellScan& cell, Summary& out) {
  ScratchVector<Group> groups;
  groups.assign(cell.groups, Group{});
  const std::span<const PolygonId> ids = cell.ids();
  for (std::uint32_t i = 0; i < cell.group_of.size(); ++i) {
    const std::uint32_t g = cell.group_of[i];
    if (g == kNotSolid) continue;
    const IslandKey key = IslandKey::of(ids[i]);
    if (groups[g].key.count == 0) {
      groups[g] = {cell.anchored[g] != 0, key, key.min_id, cell.box};
    } else {
      groups[g].key.add(key);
    }
  }
  out.ports.clear();
  for (std::size_t k = 0; k < cell.ports.size(); ++k) {
    out.side_begin[k] = static_cast<std::uint32_t>(out.ports.size());
    out.ports.insert(out.ports.end(), cell.ports[k].begin(), cell.ports[k].end());
  }
  out.side_begin[4] = static_cast<std::uint32_t>(out.ports.size());
  ScratchUnionFind uf(groups.size());
  finish(groups, uf, out);
}

void combine(const Box64& node, std::span<const Box64> children,
             std::span<const Summary* const> summaries, std::size_t& matched, Summary& out) {
  ScratchVector<std::uint32_t> offset;
  ScratchVector<Group> groups;
  offset.resize(children.size());
  for (std::size_t c = 0; c < children.size(); ++c) {
    offset[c] = static_cast<std::uint32_t>(groups.size());
    groups.insert(groups.end(), summaries[c]->groups.begin(), summaries[c]->groups.end());
  }
  ScratchUnionFind uf(groups.size());
  for (std::size_t a = 0; a < children.size(); ++a)
    for (std::size_t b = 0; b < children.size(); ++b) {
      const Box64 &ba = children[a], &bb = children[b];
      const Summary &sa = *summaries[a], &sb = *summaries[b];
      if (ba.max.x == bb.min.x && ba.min.y < bb.max.y && bb.min.y < ba.max.y)
        match(sa.side(Side::kRight), offset[a], sb.side(Side::kLeft), offset[b], uf, matched);
      if (ba.max.y == bb.min.y && ba.min.x < bb.max.x && bb.min.x < ba.max.x)
        match(sa.side(Side::kTop), offset[a], sb.side(Side::kBottom), offset[b], uf, matched);
    }
  out.ports.clear();
  for (Side s : kSides) {
    const std::size_t begin = out.ports.size();
    out.side_begin[side_index(s)] = static_cast<std::uint32_t>(begin);
    for (std::size_t c = 0; c < children.size(); ++c) {
      if (!on_side_of(children[c], s, node)) continue;
      for (Port p : summaries[c]->side(s)) {
        p.group += offset[c];
        out.ports.push_back(p);
      }
    }
    std::sort(out.ports.begin() + static_cast<std::ptrdiff_t>(begin), out.ports.end(),
              [](const Port& l, const Port& r) { return l.lo < r.lo; });
  }
  out.side_begin[4] = static_cast<std::uint32_t>(out.ports.size());
  finish(groups, uf, out);
}

}  // namespace edgeland::game_detail
