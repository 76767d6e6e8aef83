#include "surface_segments.hpp"

#include <algorithm>

namespace edgeland::game_detail {
namespace {

Span span_of(Side side, Point64 a, Point64 b) {
  return {std::min(along(side, a), along(side, b)), std::max(along(side, a), along(side, b))};
}

// The extent of the box's side along it.
Span side_extent(const Box64& box, Side side) {
  return side == Side::kBottom || side == Side::kTop ? Span{box.min.x, box.max.x}
                                                     : Span{box.min.y, box.max.y};
}

// Ascending spans with touching or overlapping ones joined: the cover as a union, the same
// whichever way the neighbours' polygons happen to be cut along the line.
void merge_spans(std::vector<Span>& spans) {
  std::sort(spans.begin(), spans.end(), [](const Span& l, const Span& r) { return l.lo < r.lo; });
  std::size_t kept = 0;
  for (const Span& s : spans) {
    if (kept > 0 && s.lo <= spans[kept - 1].hi)
      spans[kept - 1].hi = std::max(spans[kept - 1].hi, s.hi);
    else
      spans[kept++] = s;
  }
  spans.resize(kept);
}

}  // namespace

// One pass over the neighbours' edges for all four sides (the neighbours' polygons are whole,
// most of their edges far from the box).
SideSpans side_covers(const CellPolygons& cell, const PhysicsMaterials& materials) {
  SideSpans out;
  for (const CellPolygon& p : cell.around) {
    if (!materials.is_solid(p.material)) continue;
    const Polygon& ring = *p.ring;
    for (std::size_t j = 0; j < ring.size(); ++j) {
      const Point64 a = ring[j], b = ring[(j + 1) % ring.size()];
      if (a.x != b.x && a.y != b.y) continue;  // on no side line
      const auto side = side_of(cell.box, a, b);
      if (!side) continue;
      // Running against this cell's ports on that side.
      const bool against = *side == Side::kBottom || *side == Side::kRight
                               ? along(*side, a) > along(*side, b)
                               : along(*side, a) < along(*side, b);
      if (!against) continue;
      const Span s = span_of(*side, a, b), extent = side_extent(cell.box, *side);
      const Span cut{std::max(s.lo, extent.lo), std::min(s.hi, extent.hi)};
      if (cut.lo < cut.hi) out.sides[static_cast<std::size_t>(*side)].push_back(cut);
    }
  }
  for (std::vector<Span>& spans : out.sides) merge_spans(spans);
  return out;
}

SideSpans port_spans(const SolidBoundary& solid) {
  SideSpans out;
  for (Side side : kSides) {
    std::vector<Span>& spans = out.sides[static_cast<std::size_t>(side)];
    for (const BoundaryPiece& p : solid.ports[static_cast<std::size_t>(side)])
      spans.push_back(span_of(side, p.a, p.b));
    merge_spans(spans);
  }
  return out;
}

namespace {

// One side's span ends in a flattened list.
std::span<const std::int64_t> flat_side(std::span<const std::int64_t> flat, Side side) {
  std::size_t at = 0;
  for (Side s : kSides) {
    const auto count = static_cast<std::size_t>(flat[at]);
    if (s == side) return flat.subspan(at + 1, 2 * count);
    at += 1 + 2 * count;
  }
  return {};
}

}  // namespace

std::vector<std::int64_t> flatten(const SideSpans& spans_per_side) {
  std::vector<std::int64_t> out;
  for (const std::vector<Span>& spans : spans_per_side.sides) {
    out.push_back(static_cast<std::int64_t>(spans.size()));
    for (const Span& s : spans) {
      out.push_back(s.lo);
      out.push_back(s.hi);
    }
  }
  return out;
}

SideSpans covers_from_ports(const Box64& box, std::span<const NeighbourPorts> neighbours) {
  SideSpans out;
  for (Side side : kSides) {
    const Span extent = side_extent(box, side);
    std::vector<Span>& spans = out.sides[static_cast<std::size_t>(side)];
    for (const NeighbourPorts& n : neighbours) {
      if (!across(box, side, n.box)) continue;
      const std::span<const std::int64_t> ports = flat_side(n.ports, opposite(side));
      for (std::size_t k = 0; k + 1 < ports.size(); k += 2) {
        const Span cut{std::max(ports[k], extent.lo), std::min(ports[k + 1], extent.hi)};
        if (cut.lo < cut.hi) spans.push_back(cut);
      }
    }
    merge_spans(spans);
  }
  return out;
}

namespace {

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
  return on_side_of(box, side, world);
}

std::vector<SurfaceSegment> surface_segments(const CellPolygons& cell, const SolidBoundary& solid,
                                             const SideSpans& covers, const Box64& world,
                                             const SurfaceOptions& options) {
  std::vector<SurfaceSegment> out;
  for (const BoundaryPiece& p : solid.free) out.push_back({p.a, p.b, cell.own[p.polygon].material});
  for (Side side : kSides) {
    if (on_world_border(cell.box, side, world)) {
      if (options.border_wall) add_wall(cell, side, solid, out);
      continue;
    }
    for (const BoundaryPiece& p : solid.ports[static_cast<std::size_t>(side)])
      add_uncovered(cell.box, side, p.a, p.b, cell.own[p.polygon].material,
                    covers.sides[static_cast<std::size_t>(side)], out);
  }
  return out;
}

}  // namespace edgeland::game_detail
