#pragma once
// Stage 2 of the surface (game/README.md): a cell's surface segments. Its free pieces, the parts
// of its ports that no solid of a neighbour covers from across the side (a port on the world
// border is never surface), and, with a border wall, the parts of its world-border sides that
// its own solid does not cover (solid, the outside, on their left).
#include <span>
#include <vector>

#include "edgeland/game/surface_chains.hpp"
#include "solid_boundary.hpp"

namespace edgeland::game_detail {

struct SurfaceSegment {
  Point64 a, b;                // solid on the left
  Material material = kEmpty;  // that solid's material (0 for a wall)
};

// A closed interval of positions along a side.
struct Span {
  std::int64_t lo = 0, hi = 0;
  friend bool operator==(const Span&, const Span&) = default;
};

// Intervals along each side of a cell, per Side: merged, ascending, disjoint.
struct SideSpans {
  std::array<std::vector<Span>, 4> sides;
  friend bool operator==(const SideSpans&, const SideSpans&) = default;
};

// The cell's COVERS: where solid of the neighbours lies across each side (their solid edges on
// the side's line run against the cell's ports), cut to the side's extent. With the cell's own
// polygons this is all stage 2 reads, so a cell whose polygons and covers did not change keeps
// its chains (surface_tracker.cpp). O(n log n) in the neighbours' edges.
SideSpans side_covers(const CellPolygons& cell, const PhysicsMaterials& materials);

// Where the cell's own solid lies on each side (its ports): what its neighbours' covers read
// of it. O(n log n) in the ports.
SideSpans port_spans(const SolidBoundary& solid);

// Spans as one list (per side: the count, then each span's ends), as a tracker keeps a cell's
// covers and ports.
std::vector<std::int64_t> flatten(const SideSpans& spans);

// A cell next to another, with its ports flattened.
struct NeighbourPorts {
  Box64 box;
  std::span<const std::int64_t> ports;
};

// The same covers as side_covers, from the neighbours' ports instead of their polygons: a
// neighbour's solid edges on a shared line are its ports there (every polygon lies in its cell),
// so the cover of a side is the union of the ports of the cells across it on their opposite
// side, cut to the side's extent. `neighbours` may hold any cells; those not across a side of
// `box` by a positive length add nothing. O(n log n) in the ports.
SideSpans covers_from_ports(const Box64& box, std::span<const NeighbourPorts> neighbours);

// O(n log n) in the cell's edges along its sides.
std::vector<SurfaceSegment> surface_segments(const CellPolygons& cell, const SolidBoundary& solid,
                                             const SideSpans& covers, const Box64& world,
                                             const SurfaceOptions& options);

// Whether the box's side lies on the world box's border.
bool on_world_border(const Box64& box, Side side, const Box64& world);

}  // namespace edgeland::game_detail
