#pragma once
// Stage 1 of game/README.md for one cell, read once and kept: the cell's polygons, its solid
// boundary cut into free pieces, ports and contacts, its solid grouped into pieces (contacts
// joined by a union-find), each group's ports on the cell's sides and whether it is anchored,
// and where its solid lies on each side. Everything the chains of the cell and of its
// neighbours, and the island summaries, need of its polygons: after a scan nothing reads them
// again (game_state.hpp).
#include <array>
#include <cstdint>
#include <vector>

#include "edgeland/spatial/landscape.hpp"
#include "side_spans.hpp"
#include "solid_boundary.hpp"
#include "union_find.hpp"

namespace edgeland::game_detail {

inline constexpr std::uint32_t kNotSolid = static_cast<std::uint32_t>(-1);

// A port as an interval of the side: lo < hi along it (x on the bottom and top, y on the sides).
struct Port {
  std::int64_t lo = 0, hi = 0;
  std::uint32_t group = 0;  // the piece of solid it belongs to (a class of the summary)
};

struct CellScan {
  Box64 box;
  std::optional<CellContents> contents;  // the polygons (shared with the landscape)
  std::vector<Material> materials;       // per polygon
  SolidBoundary boundary;
  std::vector<std::uint32_t> group_of;  // per polygon: its group, or kNotSolid
  std::uint32_t groups = 0;
  std::vector<std::uint8_t> anchored;  // per group
  // Ports per side not on the world border, ascending along the side, with their groups.
  std::array<std::vector<Port>, 4> ports;
  // Where the cell's own solid lies on each side (what the neighbours' covers read of it).
  SideSpans port_spans;

  std::span<const PolygonId> ids() const { return contents->ids(); }
};

// Storage a scan reuses from one cell to the next.
struct ScanScratch {
  std::vector<CellPolygon> polygons;
  std::vector<LineEdge> edges;
  UnionFind groups;
  std::vector<std::uint32_t> of_root;
};

// Scans `cell` into `out` (its storage reused). O(n log n) for the cell's n edges.
void scan_cell(CellContents cell, const Box64& world, const PhysicsMaterials& materials,
               CellScan& out, ScanScratch& scratch);

// The cell of `world` whose box is `box`, scanned.
CellScan scan_cell(const Landscape& world, const Box64& box, const PhysicsMaterials& materials);

// The boxes of every cell, in tree order.
std::vector<Box64> all_cells(const Landscape& world);

}  // namespace edgeland::game_detail
