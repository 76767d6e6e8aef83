#include "cell_scan.hpp"

#include <algorithm>

namespace edgeland::game_detail {
namespace {

// The cell's polygons as stage 1 reads them.
void read_polygons(const CellContents& cell, std::vector<CellPolygon>& out,
                   std::vector<Material>& materials) {
  const std::span<const Polygon> rings = cell.polygons();
  out.resize(rings.size());
  materials.resize(rings.size());
  for (std::size_t i = 0; i < rings.size(); ++i) {
    materials[i] = cell.material(i);
    out[i] = {materials[i], &rings[i]};
  }
}

// Numbers the union-find roots of the solid polygons 0, 1, ... in polygon order; a group is
// anchored when it holds an anchored material.
void number_groups(CellScan& s, UnionFind& uf, std::vector<std::uint32_t>& of_root,
                   const PhysicsMaterials& materials) {
  const std::size_t n = s.materials.size();
  s.group_of.assign(n, kNotSolid);
  of_root.assign(n, kNotSolid);
  s.groups = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!materials.is_solid(s.materials[i])) continue;
    std::uint32_t& g = of_root[uf.find(i)];
    if (g == kNotSolid) g = s.groups++;
    s.group_of[i] = g;
  }
  s.anchored.assign(s.groups, 0);
  for (std::uint32_t i = 0; i < n; ++i)
    if (s.group_of[i] != kNotSolid && materials.is_anchored(s.materials[i]))
      s.anchored[s.group_of[i]] = 1;
}

std::int64_t lo_along(Side side, const BoundaryPiece& p) {
  return std::min(along(side, p.a), along(side, p.b));
}
std::int64_t hi_along(Side side, const BoundaryPiece& p) {
  return std::max(along(side, p.a), along(side, p.b));
}

// Ports with their groups off the world border (solid lying on the border anchors its group
// instead), and each side's merged spans.
void collect_ports(CellScan& s, const Box64& world) {
  for (Side side : kSides) {
    const auto k = static_cast<std::size_t>(side);
    const bool border = on_side_of(s.box, side, world);
    std::vector<Port>& ports = s.ports[k];
    std::vector<Span>& spans = s.port_spans.sides[k];
    ports.clear();
    spans.clear();
    for (const BoundaryPiece& p : s.boundary.ports[k]) {
      const std::uint32_t g = s.group_of[p.polygon];
      spans.push_back({lo_along(side, p), hi_along(side, p)});
      if (border)
        s.anchored[g] = 1;
      else
        ports.push_back({lo_along(side, p), hi_along(side, p), g});
    }
    std::sort(ports.begin(), ports.end(), [](const Port& l, const Port& r) { return l.lo < r.lo; });
    merge_spans(spans);
  }
}

}  // namespace

void scan_cell(CellContents cell, const Box64& world, const PhysicsMaterials& materials,
               CellScan& out, ScanScratch& scratch) {
  out.box = cell.box();
  read_polygons(cell, scratch.polygons, out.materials);
  out.contents = std::move(cell);
  solid_boundary(out.box, scratch.polygons, materials, out.boundary, scratch.edges);
  scratch.groups.reset(out.materials.size());
  for (const auto& [p, q] : out.boundary.contacts) scratch.groups.unite(p, q);
  number_groups(out, scratch.groups, scratch.of_root, materials);
  collect_ports(out, world);
}

CellScan scan_cell(const Landscape& world, const Box64& box, const PhysicsMaterials& materials) {
  CellScan out;
  ScanScratch scratch;
  scan_cell(*world.cell(box), world.world(), materials, out, scratch);
  return out;
}

std::vector<Box64> all_cells(const Landscape& world) {
  std::vector<Box64> out;
  world.cells_in(world.world(), [&](const CellView& c) {
    out.push_back(c.box);
    return true;
  });
  return out;
}

}  // namespace edgeland::game_detail
