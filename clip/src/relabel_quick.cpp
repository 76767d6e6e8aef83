// The quick cases of a cell's overlay (relabel_quick.hpp). They are those where relabel()'s
// arrangement would meet no crossing at a non-integer point, so snap rounding moves nothing and
// relabel() returns the canonical decomposition of the relabeled regions (relabel.hpp); when
// those regions are the cell's own, that is the cell's content (a canonical decomposition), and
// when the shape covers the cell they are one region or none.
#include "relabel_quick.hpp"

#include <algorithm>
#include <vector>

#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/box_queries.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "grown_box.hpp"

namespace edgeland::detail {
namespace {

// The member contains the whole cell: no edge of it meets the cell's open interior, and a point
// of that interior (the corner min, by the half-open rule) is inside it. Its edges then touch
// the cell box at integer points only (a segment that meets a closed box but not its interior
// touches it at a corner, along a side, or at one of its own ends).
bool covers(const Polygon& member, const Box64& cell) {
  for (std::size_t i = 0; i < member.size(); ++i)
    if (segment_meets_open_box(ring_edge(member, i), cell)) return false;
  return inside_half_open(cell.min, member);
}

// Whether the cell's polygons leave some of its box uncovered (material 0 present).
bool has_empty_space(const CellInput& cell) {
  return twice_signed_area(cell.polygons()) < twice_signed_area(box_ring(cell.box));
}

// The shape covers the cell: each label present (0 where the polygons leave space) becomes its
// relabeled value. kUnchanged: every one stays; kUniform: all become `to` (the content is then
// the cell box of `to`, or nothing); kMixed: anything else (left to relabel()).
enum class Covered { kUnchanged, kUniform, kMixed };
Covered relabel_covered(const CellInput& cell, std::span<const RegionLabel> table,
                        RegionLabel& to) {
  std::vector<RegionLabel> present = cell.labels();
  if (present.empty() || has_empty_space(cell)) present.push_back(kNoRegion);
  to = relabeled(table, present.front());
  bool all_stay = true, uniform = true;
  for (RegionLabel l : present) {
    all_stay = all_stay && relabeled(table, l) == l;
    uniform = uniform && relabeled(table, l) == to;
  }
  if (all_stay) return Covered::kUnchanged;
  return uniform ? Covered::kUniform : Covered::kMixed;
}

LabeledSet uniform_content(const Box64& box, RegionLabel to) {
  if (to == kNoRegion) return {};
  return {ValidSet(PolygonSet{box_ring(box)}), {to}};
}

// Whether some edge of `member` has a point in common with some edge of the cell's polygons.
bool meets_a_boundary(const CellInput& cell, const Polygon& member, const Box64& member_box) {
  const PolygonSet& polys = cell.polygons();
  for (std::size_t q = 0; q < polys.size(); ++q) {
    if (!cell.boxes[q].overlaps(member_box)) continue;
    const Polygon& poly = polys[q];
    for (std::size_t j = 0; j < poly.size(); ++j) {
      const Segment f = ring_edge(poly, j);
      const Box64 fb = segment_box(f);
      if (!fb.overlaps(member_box)) continue;
      for (std::size_t i = 0; i < member.size(); ++i) {
        const Segment e = ring_edge(member, i);
        if (segment_box(e).overlaps(fb) && intersect(e, f).relation != SegmentRelation::kDisjoint)
          return true;
      }
    }
  }
  return false;
}

// A member that meets no boundary of the cell lies in one face of its polygons and may hold
// whole polygons: the relabel leaves it all as it is when each of those keeps its label.
bool leaves_all_as_is(const CellInput& cell, const Polygon& member, const Box64& member_box,
                      std::span<const RegionLabel> table) {
  const PolygonSet& polys = cell.polygons();
  RegionLabel around = kNoRegion;  // the label of the face the member lies in
  for (std::size_t q = 0; q < polys.size(); ++q) {
    if (!cell.boxes[q].overlaps(member_box)) continue;
    if (locate(member.front(), polys[q]) == PointLocation::kInside) around = cell.labels()[q];
    if (locate(polys[q].front(), member) == PointLocation::kInside &&
        relabeled(table, cell.labels()[q]) != cell.labels()[q])
      return false;
  }
  return relabeled(table, around) == around;
}

// Every polygon of the cell lies at least two units (L-infinity, from its box) from every edge
// of the shape: no crossing, no hot pixel and no moved segment of relabel()'s arrangement comes
// near them (snap rounding moves segments by less than a unit, and only those meeting a hot
// pixel; the window's edges, on integer lines, pass through the centre of every hot pixel they
// meet). Each polygon is then wholly inside or wholly outside each member.
bool clear_of_the_shape(const CellInput& cell, const ValidSet& shape, const ShapeNearWindow& near) {
  const Box64 reach = grown(cell.box, 2);
  for (std::size_t k = 0; k < near.members.size(); ++k) {
    const Polygon& member = shape.polygons()[near.members[k]];
    for (std::size_t i = 0; i < member.size(); ++i) {
      const Segment edge = ring_edge(member, i);
      const Box64 e = grown(segment_box(edge), 2);
      if (!e.overlaps(reach)) continue;
      for (const Box64& b : cell.boxes)
        if (b.overlaps(e) && segment_meets_open_box(edge, grown(b, 2))) return false;
    }
  }
  return true;
}

// With every polygon clear of the shape: no polygon inside a member changes its label, and the
// uncovered space keeps its own (0).
bool clear_and_kept(const CellInput& cell, const ValidSet& shape, const ShapeNearWindow& near,
                    std::span<const RegionLabel> table) {
  if (relabeled(table, kNoRegion) != kNoRegion) return false;
  const PolygonSet& polys = cell.polygons();
  for (std::size_t q = 0; q < polys.size(); ++q) {
    const RegionLabel l = cell.labels()[q];
    if (relabeled(table, l) == l) continue;
    for (std::size_t k = 0; k < near.members.size(); ++k)
      if (near.boxes[k].contains(cell.boxes[q]) &&
          locate(polys[q].front(), shape.polygons()[near.members[k]]) == PointLocation::kInside)
        return false;
  }
  return true;
}

// Whether the polygon edge f lies on a side line of the cell box (cell polygons lie in the
// closed box, so both ends on one side line put the whole edge on it).
bool on_cell_side(const Segment& f, const Box64& box) {
  return (f.a.x == f.b.x && (f.a.x == box.min.x || f.a.x == box.max.x)) ||
         (f.a.y == f.b.y && (f.a.y == box.min.y || f.a.y == box.max.y));
}

bool in_open_box(Point64 p, const Box64& b) {
  return b.min.x < p.x && p.x < b.max.x && b.min.y < p.y && p.y < b.max.y;
}

// Every edge of the cell's polygons off the cell's side lines (an "inner" edge) lies at least two
// units (L-infinity, from its box) from every edge of the shape. Snap rounding then never moves
// a polygon edge: every hot pixel of relabel()'s arrangement is centred within half a unit of a
// shape edge (a rounded crossing of a shape edge with a side line, a side edge or the window's
// ring, or a vertex a moved shape edge's route jumps over), so inner edges meet none, and an
// edge on a side line meets an integer-centred pixel only through its centre.
bool inner_edges_clear(const CellInput& cell, const ValidSet& shape, const ShapeNearWindow& near) {
  const PolygonSet& polys = cell.polygons();
  for (std::uint32_t member : near.members) {
    const Polygon& m = shape.polygons()[member];
    for (std::size_t i = 0; i < m.size(); ++i) {
      const Segment e = ring_edge(m, i);
      const Box64 eb = segment_box(e);
      if (!grown(eb, 2).overlaps(cell.box)) continue;
      for (std::size_t q = 0; q < polys.size(); ++q) {
        if (!grown(cell.boxes[q], 2).overlaps(eb)) continue;
        for (std::size_t j = 0; j < polys[q].size(); ++j) {
          const Segment f = ring_edge(polys[q], j);
          const Box64 reach = grown(segment_box(f), 2);
          if (reach.overlaps(eb) && !on_cell_side(f, cell.box) && segment_meets_open_box(e, reach))
            return false;
        }
      }
    }
  }
  return true;
}

// The label of the region holding p, a point of the open cell box two units or more from every
// inner edge: the polygon p is inside, or 0 (empty space); nullopt if p is on a boundary.
std::optional<RegionLabel> region_at(const CellInput& cell, Point64 p) {
  const PolygonSet& polys = cell.polygons();
  for (std::size_t q = 0; q < polys.size(); ++q) {
    if (!cell.boxes[q].contains(p)) continue;
    switch (locate(p, polys[q])) {
      case PointLocation::kInside:
        return cell.labels()[q];
      case PointLocation::kOnBoundary:
        return std::nullopt;  // Not reached when the inner edges are clear: kept for safety.
      case PointLocation::kOutside:
        break;
    }
  }
  return kNoRegion;
}

// The first vertex of every chain of inner edges of polygon q (a maximal run of consecutive
// inner edges along its ring; the whole ring when no edge lies on a side line).
void inner_chain_starts(const CellInput& cell, std::size_t q, std::vector<Point64>& out) {
  const Polygon& poly = cell.polygons()[q];
  const std::size_t n = poly.size();
  bool previous = !on_cell_side(ring_edge(poly, n - 1), cell.box), any_side = !previous;
  const std::size_t before = out.size();
  for (std::size_t j = 0; j < n; ++j) {
    const bool inner = !on_cell_side(ring_edge(poly, j), cell.box);
    if (inner && !previous) out.push_back(poly[j]);
    any_side = any_side || !inner;
    previous = inner;
  }
  if (!any_side && out.size() == before) out.push_back(poly.front());
}

// With the inner edges clear (inner_edges_clear, tested after this), every region (polygon
// interior or empty space) of the open cell that the member meets keeps its label. The member's
// boundary crosses no inner edge, so each piece of it in the open cell lies in one region,
// which holds a vertex of it as no edge of the member crosses the cell without one (else:
// false). A region holding no such piece is wholly inside the member or outside it: a polygon
// as a vertex of its inner edges says (two units from the member's boundary, and its interior
// beside it on the same side), and empty space only if one of the inner edges around it is
// inside the member, each chain of inner edges lying wholly on one side.
bool member_keeps_what_it_meets(const CellInput& cell, const Polygon& m,
                                std::span<const RegionLabel> table) {
  for (Point64 v : m) {
    if (!in_open_box(v, cell.box)) continue;
    const std::optional<RegionLabel> l = region_at(cell, v);
    if (!l || relabeled(table, *l) != *l) return false;
  }
  bool enters = false;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Segment e = ring_edge(m, i);
    if (!segment_meets_open_box(e, cell.box)) continue;
    enters = true;
    if (!in_open_box(e.a, cell.box) && !in_open_box(e.b, cell.box)) return false;
  }
  if (!enters) return !covers(m, cell.box);  // outside, or covering (left to covered_answer)
  const Box64 mb = *bounding_box(m);
  const bool fills_space = relabeled(table, kNoRegion) != kNoRegion;
  std::vector<Point64> starts;
  for (std::size_t q = 0; q < cell.labels().size(); ++q) {
    const RegionLabel l = cell.labels()[q];
    const bool changes = relabeled(table, l) != l;
    if ((!changes && !fills_space) || !cell.boxes[q].overlaps(mb)) continue;
    starts.clear();
    inner_chain_starts(cell, q, starts);
    // One chain tells for a polygon holding no piece of the member; empty space may border any.
    if (!fills_space && starts.size() > 1) starts.resize(1);
    for (Point64 w : starts)
      if (locate(w, m) != PointLocation::kOutside) return false;
  }
  return true;
}

// Quick rejection of a shape that passes through the cell only in regions it leaves as they
// are, crossing the cell's side lines anywhere (a fill of rock into rock reaching over a cell
// line): the inner edges are clear of the shape, so relabel() moves no polygon edge, and every
// face inside the shape keeps its label, so the regions and their canonical decomposition (I3)
// come back unchanged.
bool passes_only_through_kept_regions(const CellInput& cell, const ValidSet& shape,
                                      const ShapeNearWindow& near,
                                      std::span<const RegionLabel> table) {
  // The labels first: they reject most edits that do change the cell after a few point tests.
  for (std::uint32_t member : near.members)
    if (!member_keeps_what_it_meets(cell, shape.polygons()[member], table)) return false;
  return inner_edges_clear(cell, shape, near);
}

// Quick rejection: the shape changes nothing in the cell, and relabel() would round nothing
// that is kept (the cell's own regions come back). Either every polygon is clear of the shape
// and keeps its label, or the shape passes only through regions it keeps with the inner edges
// clear of it, or every member reaching the cell lies in its closed box (no window ring), meets
// no boundary there (no contact at all) and changes nothing. The case that applies, if any.
std::optional<QuickCase> changes_nothing(const CellInput& cell, const ValidSet& shape,
                                         const ShapeNearWindow& near,
                                         std::span<const RegionLabel> table) {
  if (clear_of_the_shape(cell, shape, near)) {
    if (clear_and_kept(cell, shape, near, table)) return QuickCase::kClearOfTheShape;
    return std::nullopt;
  }
  if (passes_only_through_kept_regions(cell, shape, near, table))
    return QuickCase::kThroughKeptRegions;
  if (!near.all_inside) return std::nullopt;
  for (std::size_t k = 0; k < near.members.size(); ++k) {
    const Polygon& member = shape.polygons()[near.members[k]];
    if (meets_a_boundary(cell, member, near.boxes[k])) return std::nullopt;
    if (!leaves_all_as_is(cell, member, near.boxes[k], table)) return std::nullopt;
  }
  return QuickCase::kInsideOneFace;
}

// The shape covers the cell (some member contains it): the answer when it is known.
std::optional<QuickAnswer> covered_answer(const CellInput& cell, const ValidSet& shape,
                                          const ShapeNearWindow& near,
                                          std::span<const RegionLabel> table) {
  for (std::size_t k = 0; k < near.members.size(); ++k) {
    if (!near.boxes[k].contains(cell.box) || !covers(shape.polygons()[near.members[k]], cell.box))
      continue;
    RegionLabel to = kNoRegion;
    switch (relabel_covered(cell, table, to)) {
      case Covered::kUnchanged:
        return QuickAnswer{QuickCase::kCoveredUnchanged, std::nullopt};
      case Covered::kUniform:
        return QuickAnswer{QuickCase::kCoveredUniform, uniform_content(cell.box, to)};
      case Covered::kMixed:
        return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<QuickAnswer> quick_overlay(const CellInput& cell, const ValidSet& shape,
                                         const ShapeNearWindow& near,
                                         std::span<const RegionLabel> table) {
  if (near.members.empty()) return QuickAnswer{QuickCase::kNoMemberNear, std::nullopt};
  if (cell.labels().empty() && relabeled(table, kNoRegion) == kNoRegion)
    return QuickAnswer{QuickCase::kEmptyStaysEmpty, std::nullopt};
  if (auto covered = covered_answer(cell, shape, near, table)) return covered;
  if (const auto unchanged = changes_nothing(cell, shape, near, table))
    return QuickAnswer{*unchanged, std::nullopt};
  return std::nullopt;
}

}  // namespace edgeland::detail
