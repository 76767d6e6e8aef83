#include "surface_segments.hpp"

#include <algorithm>

namespace edgeland::game_detail {
namespace {

// A closed interval of positions along a side.
struct Span {
  std::int64_t lo = 0, hi = 0;
};

Span span_of(Side side, Point64 a, Point64 b) {
  return {std::min(along(side, a), along(side, b)), std::max(along(side, a), along(side, b))};
}

// The extent of the box's side along it.
Span side_extent(const Box64& box, Side side) {
  return side == Side::kBottom || side == Side::kTop ? Span{box.min.x, box.max.x}
                                                     : Span{box.min.y, box.max.y};
}

// Solid from across the side: the neighbours' solid edges on the side's line run the other way
// (their polygons lie across the line), cut to the side's extent; ascending, disjoint.
std::vector<Span> covered_from_across(const CellPolygons& cell, Side side,
                                      const PhysicsMaterials& materials) {
  const Span extent = side_extent(cell.box, side);
  std::vector<Span> out;
  for (const CellPolygon& p : cell.around) {
    if (!materials.is_solid(p.material)) continue;
    const Polygon& ring = *p.ring;
    for (std::size_t j = 0; j < ring.size(); ++j) {
      const Point64 a = ring[j], b = ring[(j + 1) % ring.size()];
      // The neighbour's edge lies on this side's line, running against this cell's ports.
      const auto on = side_of(cell.box, a, b);
      if (!on || *on != side) continue;
      const bool against = side == Side::kBottom || side == Side::kRight
                               ? along(side, a) > along(side, b)
                               : along(side, a) < along(side, b);
      if (!against) continue;
      const Span s = span_of(side, a, b);
      const Span cut{std::max(s.lo, extent.lo), std::min(s.hi, extent.hi)};
      if (cut.lo < cut.hi) out.push_back(cut);
    }
  }
  std::sort(out.begin(), out.end(), [](const Span& l, const Span& r) { return l.lo < r.lo; });
  return out;
}

// The parts of `piece` (along `side`) outside every span of `cover` (ascending, disjoint),
// directed as the piece.
void add_uncovered(const Box64& box, Side side, Point64 a, Point64 b, Material material,
                   const std::vector<Span>& cover, std::vector<SurfaceSegment>& out) {
  const Span s = span_of(side, a, b);
  const bool ascending = along(side, a) < along(side, b);
  std::vector<Span> gaps;
  std::int64_t cursor = s.lo;
  for (const Span& c : cover) {
    if (c.hi <= cursor || c.lo >= s.hi) continue;
    if (c.lo > cursor) gaps.push_back({cursor, c.lo});
    cursor = std::max(cursor, c.hi);
  }
  if (cursor < s.hi) gaps.push_back({cursor, s.hi});
  if (!ascending) std::reverse(gaps.begin(), gaps.end());
  for (const Span& g : gaps) {
    const Point64 lo = point_on(box, side, g.lo), hi = point_on(box, side, g.hi);
    out.push_back(ascending ? SurfaceSegment{lo, hi, material} : SurfaceSegment{hi, lo, material});
  }
}

// The wall along a world-border side: where the cell's own solid does not lie on it. The outside
// is on the wall's left, so it runs clockwise around the box.
void add_wall(const CellPolygons& cell, Side side, const SolidBoundary& solid,
              std::vector<SurfaceSegment>& out) {
  std::vector<Span> own;
  for (const BoundaryPiece& p : solid.ports[static_cast<std::size_t>(side)])
    own.push_back(span_of(side, p.a, p.b));
  std::sort(own.begin(), own.end(), [](const Span& l, const Span& r) { return l.lo < r.lo; });
  const Span extent = side_extent(cell.box, side);
  const Point64 lo = point_on(cell.box, side, extent.lo), hi = point_on(cell.box, side, extent.hi);
  const bool clockwise_ascends = side == Side::kTop || side == Side::kLeft;
  if (clockwise_ascends)
    add_uncovered(cell.box, side, lo, hi, kEmpty, own, out);
  else
    add_uncovered(cell.box, side, hi, lo, kEmpty, own, out);
}

}  // namespace

bool on_world_border(const Box64& box, Side side, const Box64& world) {
  switch (side) {
    case Side::kBottom:
      return box.min.y == world.min.y;
    case Side::kRight:
      return box.max.x == world.max.x;
    case Side::kTop:
      return box.max.y == world.max.y;
    case Side::kLeft:
      return box.min.x == world.min.x;
  }
  return false;
}

std::vector<SurfaceSegment> surface_segments(const CellPolygons& cell, const SolidBoundary& solid,
                                             const Box64& world, const SurfaceOptions& options) {
  std::vector<SurfaceSegment> out;
  for (const BoundaryPiece& p : solid.free)
    out.push_back({p.a, p.b, cell.own[p.polygon].material});
  for (Side side : kSides) {
    if (on_world_border(cell.box, side, world)) {
      if (options.border_wall) add_wall(cell, side, solid, out);
      continue;
    }
    const std::vector<Span> cover = covered_from_across(cell, side, options.materials);
    for (const BoundaryPiece& p : solid.ports[static_cast<std::size_t>(side)])
      add_uncovered(cell.box, side, p.a, p.b, cell.own[p.polygon].material, cover, out);
  }
  return out;
}

}  // namespace edgeland::game_detail
