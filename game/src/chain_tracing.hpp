#pragma once
// Stage 3 of the surface (game/README.md): a cell's surface segments linked into chains. At a
// vertex the segment that follows an incoming one is the first outgoing segment clockwise from
// the way back (the face-tracing rule: it keeps the same piece of solid on the left, so two
// pieces of solid that touch at a point stay apart). The cell sees only its own segments, so the
// sweep stops where the plane around the vertex leaves the cell (around_vertex.hpp): there the
// chain ends, and the surface goes on in a neighbour cell. Then collinear points are dropped
// where the material does not change.
#include <span>
#include <vector>

#include "edgeland/kernel/around_vertex.hpp"
#include "surface_segments.hpp"

namespace edgeland::game_detail {

struct TracedChain {
  std::vector<Point64> points;
  std::vector<Material> materials;  // per segment
  bool closed = false;
};

// The open quadrants around p (in the cell's box) that are not the cell's: quadrants outside the
// box, except those outside the world when the border is a wall (the outside is solid then, and
// its walls are the cell's own segments).
BlockedQuadrants quadrants_not_in_cell(const Box64& cell, const Box64& world, bool border_wall,
                                       Point64 p);
// The quadrants around p outside the world, for a sweep over all cells: blocked unless the
// border is a wall.
BlockedQuadrants quadrants_outside_world(const Box64& world, bool border_wall, Point64 p);

// Storage trace_chains reuses from one cell to the next.
struct TraceScratch {
  std::vector<std::size_t> order, next;
  std::vector<Point64> directions;
  std::vector<std::uint8_t> has_previous, used;
};

// Open chains first (in order of their first segment's start), then closed ones, each closed one
// starting at its smallest point; appended to `out`. O(n log n).
void trace_chains(std::span<const SurfaceSegment> segments, const Box64& cell, const Box64& world,
                  bool border_wall, TraceScratch& scratch, std::vector<TracedChain>& out);

// Drops the points of an open or closed chain where it goes straight on in the same material,
// and starts a closed chain at its smallest point: the chain's canonical form.
void make_canonical(TracedChain& chain);

}  // namespace edgeland::game_detail
