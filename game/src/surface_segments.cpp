#include "surface_segments.hpp"

#include <algorithm>

namespace edgeland::game_detail {
namespace {

Span span_of(Side side, Point64 a, Point64 b) {
  return {std::min(along(side, a), along(side, b)), std::max(along(side, a), along(side, b))};
}

// The parts of the piece a -> b along `side` outside every span of `cover` (ascending,
// disjoint), appended to `out` directed as the piece.
void add_uncovered(const Box64& box, Side side, Point64 a, Point64 b, Material material,
                   const std::vector<Span>& cover, std::vector<SurfaceSegment>& out) {
  const Span s = span_of(side, a, b);
  const bool ascending = along(side, a) < along(side, b);
  const std::size_t first = out.size();
  const auto emit = [&](std::int64_t lo, std::int64_t hi) {
    const Point64 l = point_on(box, side, lo), h = point_on(box, side, hi);
    out.push_back(ascending ? SurfaceSegment{l, h, material} : SurfaceSegment{h, l, material});
  };
  std::int64_t cursor = s.lo;
  for (const Span& c : cover) {
    if (c.hi <= cursor || c.lo >= s.hi) continue;
    if (c.lo > cursor) emit(cursor, c.lo);
    cursor = std::max(cursor, c.hi);
  }
  if (cursor < s.hi) emit(cursor, s.hi);
  if (!ascending) std::reverse(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

// The wall along a world-border side: where the cell's own solid does not lie on it. The outside
// is on the wall's left, so it runs clockwise around the box.
void add_wall(const CellScan& cell, Side side, std::vector<SurfaceSegment>& out) {
  const std::vector<Span>& own = cell.port_spans.sides[static_cast<std::size_t>(side)];
  const Span extent = side_extent(cell.box, side);
  const Point64 lo = point_on(cell.box, side, extent.lo), hi = point_on(cell.box, side, extent.hi);
  const bool clockwise_ascends = side == Side::kTop || side == Side::kLeft;
  if (clockwise_ascends)
    add_uncovered(cell.box, side, lo, hi, kEmpty, own, out);
  else
    add_uncovered(cell.box, side, hi, lo, kEmpty, own, out);
}

}  // namespace

void covers_from_ports(const Box64& box, std::span<const NeighbourSpans> neighbours,
                       SideSpans& out) {
  for (Side side : kSides) {
    const Span extent = side_extent(box, side);
    std::vector<Span>& spans = out.sides[static_cast<std::size_t>(side)];
    spans.clear();
    for (const NeighbourSpans& n : neighbours) {
      if (!across(box, side, n.box)) continue;
      for (const Span& p : n.ports->sides[static_cast<std::size_t>(opposite(side))]) {
        const Span cut{std::max(p.lo, extent.lo), std::min(p.hi, extent.hi)};
        if (cut.lo < cut.hi) spans.push_back(cut);
      }
    }
    merge_spans(spans);
  }
}

void surface_segments(const CellScan& cell, const SideSpans& covers, const Box64& world,
                      bool border_wall, std::vector<SurfaceSegment>& out) {
  out.clear();
  for (const BoundaryPiece& p : cell.boundary.free)
    out.push_back({p.a, p.b, cell.materials[p.polygon]});
  for (Side side : kSides) {
    const auto k = static_cast<std::size_t>(side);
    if (on_side_of(cell.box, side, world)) {
      if (border_wall) add_wall(cell, side, out);
      continue;
    }
    for (const BoundaryPiece& p : cell.boundary.ports[k])
      add_uncovered(cell.box, side, p.a, p.b, cell.materials[p.polygon], covers.sides[k], out);
  }
}

}  // namespace edgeland::game_detail
