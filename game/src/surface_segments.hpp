#pragma once
// Stage 2 of the surface (game/README.md): a cell's surface segments. Its free pieces, the parts
// of its ports that no solid of a neighbour covers from across the side (a port on the world
// border is never surface), and, with a border wall, the parts of its world-border sides that
// its own solid does not cover (solid, the outside, on their left).
#include <span>
#include <vector>

#include "cell_scan.hpp"

namespace edgeland::game_detail {

struct SurfaceSegment {
  Point64 a, b;                // solid on the left
  Material material = kEmpty;  // that solid's material (0 for a wall)
};

// A cell next to another, with where its solid lies on its sides (CellScan::port_spans).
struct NeighbourSpans {
  Box64 box;
  const SideSpans* ports = nullptr;
};

// The cell's COVERS: where solid of the neighbours lies across each side, cut to the side's
// extent. A neighbour's solid edges on a shared line are its ports there (every polygon lies in
// its cell), so the cover of a side is the union of the ports of the cells across it on their
// opposite side. `neighbours` may hold any cells; those not across a side of `box` add nothing.
// With the cell's own scan this is all stage 2 reads, so a cell whose polygons and covers did
// not change keeps its chains. Into `out` (storage reused). O(n log n) in the ports.
void covers_from_ports(const Box64& box, std::span<const NeighbourSpans> neighbours,
                       SideSpans& out);

// Stage 2 into `out` (cleared first, storage reused). O(n log n) in the cell's edges along its
// sides.
void surface_segments(const CellScan& cell, const SideSpans& covers, const Box64& world,
                      bool border_wall, std::vector<SurfaceSegment>& out);

}  // namespace edgeland::game_detail
