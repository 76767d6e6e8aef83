#include "cell_solids.hpp"

#include <algorithm>

#include "surface_segments.hpp"

namespace edgeland::game_detail {

UnionFind::UnionFind(std::size_t n) : parent_(n) {
  for (std::size_t i = 0; i < n; ++i) parent_[i] = static_cast<std::uint32_t>(i);
}

std::uint32_t UnionFind::find(std::uint32_t x) {
  while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
  return x;
}

void UnionFind::unite(std::uint32_t a, std::uint32_t b) {
  a = find(a);
  b = find(b);
  if (a != b) parent_[std::max(a, b)] = std::min(a, b);
}

namespace {

// Numbers the union-find roots of the solid polygons 0, 1, ... in polygon order.
void number_groups(CellSolids& s, UnionFind& uf, const PhysicsMaterials& materials) {
  const std::size_t n = s.polygons.own.size();
  s.group_of.assign(n, kNotSolid);
  std::vector<std::uint32_t> of_root(n, kNotSolid);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!materials.is_solid(s.polygons.own[i].material)) continue;
    std::uint32_t& g = of_root[uf.find(i)];
    if (g == kNotSolid) g = s.groups++;
    s.group_of[i] = g;
  }
  s.anchored.assign(s.groups, false);
  for (std::uint32_t i = 0; i < n; ++i)
    if (s.group_of[i] != kNotSolid && materials.is_anchored(s.polygons.own[i].material))
      s.anchored[s.group_of[i]] = true;
}

void collect_ports(CellSolids& s, const Box64& world) {
  for (Side side : kSides) {
    const bool border = on_world_border(s.polygons.box, side, world);
    std::vector<Port>& ports = s.ports[static_cast<std::size_t>(side)];
    for (const BoundaryPiece& p : s.boundary.ports[static_cast<std::size_t>(side)]) {
      const std::uint32_t g = s.group_of[p.polygon];
      if (border) {
        s.anchored[g] = true;  // solid lying on the world border is held by it
        continue;
      }
      const std::int64_t a = along(side, p.a), b = along(side, p.b);
      ports.push_back({std::min(a, b), std::max(a, b), g});
    }
    std::sort(ports.begin(), ports.end(), [](const Port& l, const Port& r) { return l.lo < r.lo; });
  }
}

}  // namespace

CellSolids cell_solids(const Landscape& world, const Box64& cell,
                       const PhysicsMaterials& materials) {
  CellSolids s;
  s.polygons = read_cell(world, cell);
  s.boundary = solid_boundary(cell, s.polygons.own, materials);
  UnionFind uf(s.polygons.own.size());
  for (const auto& [p, q] : s.boundary.contacts) uf.unite(p, q);
  number_groups(s, uf, materials);
  collect_ports(s, world.world());
  return s;
}

}  // namespace edgeland::game_detail
