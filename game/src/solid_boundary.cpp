#include "solid_boundary.hpp"

#include <algorithm>
#include <atomic>
#include <optional>

namespace edgeland::game_detail {
namespace {

std::atomic<std::uint64_t> runs{0};

LineEdge line_edge(Point64 a, Point64 b, std::uint32_t polygon) {
  LineEdge e;
  e.line = supporting_line(a, b);
  e.forward = runs_forward(e.line, a, b);
  e.lo_point = e.forward ? a : b;
  e.hi_point = e.forward ? b : a;
  e.lo = position_on(e.line, e.lo_point);
  e.hi = position_on(e.line, e.hi_point);
  e.polygon = polygon;
  return e;
}

bool group_order(const LineEdge& l, const LineEdge& r) {
  if (!(l.line == r.line)) return l.line < r.line;
  if (l.forward != r.forward) return l.forward;
  return l.lo < r.lo;
}

// The piece [from, to] of edge e, directed as e runs.
BoundaryPiece piece_of(const LineEdge& e, Point64 from, Point64 to) {
  return e.forward ? BoundaryPiece{from, to, e.polygon} : BoundaryPiece{to, from, e.polygon};
}

// The parts of each edge of `edges` that no edge of `opposite` covers go to `free`; every pair
// overlapping with positive length is a contact (recorded when `record_contacts`). Both spans
// are sorted by lo with disjoint interiors (edges running one way along one line belong to
// polygons with disjoint interiors on the same side).
void subtract(std::span<const LineEdge> edges, std::span<const LineEdge> opposite,
              bool record_contacts, SolidBoundary& out) {
  std::size_t first = 0;
  for (const LineEdge& e : edges) {
    while (first < opposite.size() && opposite[first].hi <= e.lo) ++first;
    std::int64_t cursor = e.lo;
    Point64 cursor_point = e.lo_point;
    for (std::size_t k = first; k < opposite.size() && opposite[k].lo < e.hi; ++k) {
      const LineEdge& o = opposite[k];
      if (record_contacts)
        out.contacts.push_back({std::min(e.polygon, o.polygon), std::max(e.polygon, o.polygon)});
      if (o.lo > cursor) out.free.push_back(piece_of(e, cursor_point, o.lo_point));
      if (o.hi > cursor) {
        cursor = o.hi;
        cursor_point = o.hi_point;
      }
    }
    if (cursor < e.hi) out.free.push_back(piece_of(e, cursor_point, e.hi_point));
  }
}

// One supporting line: its forward and backward edges cut each other.
void cut_line_group(std::span<const LineEdge> group, SolidBoundary& out) {
  const auto split =
      std::find_if(group.begin(), group.end(), [](const LineEdge& e) { return !e.forward; });
  const std::span<const LineEdge> forward(group.begin(), split), backward(split, group.end());
  subtract(forward, backward, true, out);
  subtract(backward, forward, false, out);
}

void sort_ports(std::vector<BoundaryPiece>& ports, Side side) {
  std::sort(ports.begin(), ports.end(), [side](const BoundaryPiece& l, const BoundaryPiece& r) {
    // Counter-clockwise along the side: ascending on the bottom and right, descending on top
    // and left.
    const bool ascending = side == Side::kBottom || side == Side::kRight;
    return ascending ? along(side, l.a) < along(side, r.a) : along(side, l.a) > along(side, r.a);
  });
}

}  // namespace

std::optional<Side> side_of(const Box64& box, Point64 a, Point64 b) {
  if (a.y == b.y && a.y == box.min.y) return Side::kBottom;
  if (a.x == b.x && a.x == box.max.x) return Side::kRight;
  if (a.y == b.y && a.y == box.max.y) return Side::kTop;
  if (a.x == b.x && a.x == box.min.x) return Side::kLeft;
  return std::nullopt;
}

std::int64_t along(Side side, Point64 p) {
  return side == Side::kBottom || side == Side::kTop ? p.x : p.y;
}

Point64 point_on(const Box64& box, Side side, std::int64_t t) {
  switch (side) {
    case Side::kBottom:
      return {t, box.min.y};
    case Side::kRight:
      return {box.max.x, t};
    case Side::kTop:
      return {t, box.max.y};
    case Side::kLeft:
      return {box.min.x, t};
  }
  return {};
}

Side opposite(Side side) { return static_cast<Side>((static_cast<int>(side) + 2) % 4); }

namespace {

// The coordinate of the line `side` of the box lies on (y for bottom and top, x otherwise).
std::int64_t side_line(const Box64& box, Side side) {
  switch (side) {
    case Side::kBottom:
      return box.min.y;
    case Side::kRight:
      return box.max.x;
    case Side::kTop:
      return box.max.y;
    case Side::kLeft:
      return box.min.x;
  }
  return 0;
}

}  // namespace

bool across(const Box64& box, Side side, const Box64& other) {
  return side_line(other, opposite(side)) == side_line(box, side);
}

bool on_side_of(const Box64& inner, Side side, const Box64& outer) {
  return side_line(inner, side) == side_line(outer, side);
}

std::uint64_t solid_boundary_runs() { return runs.load(std::memory_order_relaxed); }

void solid_boundary(const Box64& box, std::span<const CellPolygon> polygons,
                    const PhysicsMaterials& materials, SolidBoundary& out,
                    std::vector<LineEdge>& edges) {
  runs.fetch_add(1, std::memory_order_relaxed);
  out.free.clear();
  for (auto& side : out.ports) side.clear();
  out.contacts.clear();
  edges.clear();
  for (std::uint32_t i = 0; i < polygons.size(); ++i) {
    if (!materials.is_solid(polygons[i].material)) continue;
    const Polygon& ring = *polygons[i].ring;
    for (std::size_t j = 0; j < ring.size(); ++j) {
      const Point64 a = ring[j], b = ring[(j + 1) % ring.size()];
      if (const auto side = side_of(box, a, b))
        out.ports[static_cast<std::size_t>(*side)].push_back({a, b, i});
      else
        edges.push_back(line_edge(a, b, i));
    }
  }
  std::sort(edges.begin(), edges.end(), group_order);
  for (std::size_t begin = 0; begin < edges.size();) {
    std::size_t end = begin + 1;
    while (end < edges.size() && edges[end].line == edges[begin].line) ++end;
    cut_line_group(std::span<const LineEdge>(edges).subspan(begin, end - begin), out);
    begin = end;
  }
  for (Side side : kSides) sort_ports(out.ports[static_cast<std::size_t>(side)], side);
  std::sort(out.contacts.begin(), out.contacts.end());
  out.contacts.erase(std::unique(out.contacts.begin(), out.contacts.end()), out.contacts.end());
}

}  // namespace edgeland::game_detail
