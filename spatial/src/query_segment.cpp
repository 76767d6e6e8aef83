// Queries along a segment (spatial/README.md, "Queries"): the cells the segment meets, in
// order, and in each the crossings of its polygons (kernel segment_crossings.hpp), merged into
// the material profile. Crossings at one parameter are taken together, so a seam between two
// pieces of one material (a cell line, a hole-splitting bridge) changes nothing.
#include <algorithm>

#include "edgeland/kernel/box_queries.hpp"
#include "edgeland/kernel/segment_crossings.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "node.hpp"
#include "query_args.hpp"
#include "regions.hpp"

namespace edgeland {
namespace {

using detail::Node;
using detail::NodePtr;

struct CellOnSegment {
  Fraction t0;
  const Node* cell;
};

// The cells whose closed box meets the segment (whose box is `reach`), with the parameter
// where it enters each. Boxes missing the segment's box are passed over by comparisons alone.
void cells_on(const NodePtr& n, const Segment& s, const Box64& reach,
              std::vector<CellOnSegment>& out) {
  if (!n->box.overlaps(reach)) return;
  const auto range = clip_parameters(s, n->box);
  if (!range) return;
  detail::require_loaded(*n);
  if (n->is_cell()) {
    out.push_back({range->t0, n.get()});
    return;
  }
  for (std::uint32_t i = 0; i < n->child_count; ++i) cells_on(n->children[i], s, reach, out);
}

struct Event {
  SegmentCrossing c;
  const Node* cell;
  std::uint32_t polygon;
};

// The walk along the segment: the material just behind the start, and the crossings of every
// polygon of the cells met so far that are not processed yet.
class Profile {
 public:
  explicit Profile(const Segment& s)
      : s_(s),
        reach_{{std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y)},
               {std::max(s.a.x, s.b.x), std::max(s.a.y, s.b.y)}} {}

  // Adds the crossings of the polygons of one cell.
  void add_cell(const Node& cell) {
    const PolygonSet& polys = cell.polygon_set();
    for (std::uint32_t i = 0; i < polys.size(); ++i) {
      if (!cell.boxes[i].overlaps(reach_) || !clip_parameters(s_, cell.boxes[i])) continue;
      const bool near_start = cell.boxes[i].contains(s_.a);
      const RingCrossings rc = segment_crossings(s_, polys[i], CrossingCulling::kNone, near_start);
      if (rc.inside_before) active_ = {&cell, i};
      for (const SegmentCrossing& c : rc.crossings) pending_.push_back({c, &cell, i});
    }
  }

  // Processes the pending crossings with t < limit (all when limit is null) in order; calls
  // report(crossing) for each change of material and stops when it returns false.
  template <class F>
  bool advance(const Fraction* limit, F&& report) {
    std::sort(pending_.begin(), pending_.end(), [](const Event& x, const Event& y) {
      const int c = compare(x.c.t, y.c.t);
      return c != 0 ? c < 0 : x.polygon < y.polygon;
    });
    std::size_t i = 0;
    while (i < pending_.size() && (!limit || compare(pending_[i].c.t, *limit) < 0)) {
      std::size_t j = i + 1;
      while (j < pending_.size() && compare(pending_[j].c.t, pending_[i].c.t) == 0) ++j;
      const bool go_on = group(i, j, report);
      i = j;
      if (!go_on) {
        pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(i));
        return false;
      }
    }
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(i));
    return true;
  }

 private:
  struct Active {
    const Node* cell = nullptr;
    std::uint32_t polygon = 0;
    bool operator==(const Active&) const = default;
  };
  Material material(const Active& a) const { return a.cell ? a.cell->material(a.polygon) : kEmpty; }

  // Crossings [i, j) share their parameter: the polygon inside after them is the one whose
  // net count leaves it inside (the one before, unless it left).
  template <class F>
  bool group(std::size_t i, std::size_t j, F&& report) {
    // Net count per polygon: a handful of crossings share a parameter, a flat list will do.
    struct Net {
      Active polygon;
      int count;
    };
    std::vector<Net> net;
    for (std::size_t k = i; k < j; ++k) {
      const Active a{pending_[k].cell, pending_[k].polygon};
      auto it = std::find_if(net.begin(), net.end(), [&](const Net& n) { return n.polygon == a; });
      if (it == net.end()) it = net.insert(net.end(), {a, 0});
      it->count += pending_[k].c.entering ? 1 : -1;
    }
    Active after = active_;
    for (const Net& n : net)
      if (n.polygon == active_ && n.count < 0) after = {};
    for (const Net& n : net)
      if (n.count > 0) after = n.polygon;
    const Active before = active_;
    active_ = after;
    if (material(before) == material(after)) return true;
    // The crossing of the polygon entered (or left, into empty space).
    const Active& named = after.cell ? after : before;
    const Event* e = &pending_[i];
    for (std::size_t k = i; k < j; ++k)
      if (pending_[k].cell == named.cell && pending_[k].polygon == named.polygon) e = &pending_[k];
    return report(make_crossing(*e, material(before), material(after)));
  }

  MaterialCrossing make_crossing(const Event& e, Material before, Material after) const {
    const Polygon& ring = e.cell->polygon_set()[e.polygon];
    MaterialCrossing m;
    m.t = e.c.t;
    m.point = crossing_point(s_, ring, e.c);
    m.rounded = round_to_grid(m.point);
    m.before = before;
    m.after = after;
    m.polygon = e.cell->ids[e.polygon];
    m.edge = e.c.edge;
    const Point64 a = ring[e.c.edge], b = ring[(e.c.edge + 1) % ring.size()];
    m.normal = {b.y - a.y, -(b.x - a.x)};
    return m;
  }

  Segment s_;
  Box64 reach_;
  Active active_;
  std::vector<Event> pending_;
};

// Whether the ray is inside the world just before `from` (after = false) or just after `to`
// (after = true), as material_at sees points: the segment moved by eps (1, eps), then a step
// back (or on) along it. Ties on a side line are decided by the direction, then by the move.
bool inside_beyond_end(const Box64& w, Point64 p, Point64 d, bool after) {
  const auto axis = [&](std::int64_t v, std::int64_t lo, std::int64_t hi, std::int64_t dv) {
    const std::int64_t step = after ? dv : -dv;  // the sign of the step off the end
    return (v > lo || (v == lo && step >= 0)) && (v < hi || (v == hi && step < 0));
  };
  return axis(p.x, w.min.x, w.max.x, d.x) && axis(p.y, w.min.y, w.max.y, d.y);
}

// The world box's border is no surface for rays (issue 27, point 15): where the ray enters
// the world from outside or leaves it, the change from or into the outside is not reported,
// so a ray starting on the world's edge sees the terrain, not the edge. The parameters of
// those two places, when the ray has them.
struct Border {
  std::optional<Fraction> enter, leave;
  bool at(const Fraction& t) const {
    return (enter && compare(t, *enter) == 0) || (leave && compare(t, *leave) == 0);
  }
};

Border border_of(const Box64& world, const Segment& s) {
  Border b;
  const auto range = clip_parameters(s, world);
  if (!range) return b;
  const Point64 d{s.b.x - s.a.x, s.b.y - s.a.y};
  if (!inside_beyond_end(world, s.a, d, false)) b.enter = range->t0;
  if (!inside_beyond_end(world, s.b, d, true)) b.leave = range->t1;
  return b;
}

// Walks the cells along from -> to in order of entry, reporting material changes until
// report returns false.
template <class F>
void walk(const NodePtr& root, Point64 from, Point64 to, F&& report) {
  if (from == to) return;
  const Segment s{from, to};
  std::vector<CellOnSegment> cells;
  const Box64 reach{{std::min(from.x, to.x), std::min(from.y, to.y)},
                    {std::max(from.x, to.x), std::max(from.y, to.y)}};
  cells_on(root, s, reach, cells);
  std::stable_sort(cells.begin(), cells.end(), [](const CellOnSegment& x, const CellOnSegment& y) {
    return compare(x.t0, y.t0) < 0;
  });
  Profile profile(s);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    profile.add_cell(*cells[k].cell);
    // Crossings before the next cell's first point are final: no later cell reaches them.
    const Fraction* limit = k + 1 < cells.size() ? &cells[k + 1].t0 : nullptr;
    if (!profile.advance(limit, report)) return;
  }
}

// The material changes inside the world, in order, until report returns false.
template <class F>
void walk_world(const Box64& world, const NodePtr& root, Point64 from, Point64 to, F&& report) {
  detail::require_query_point(from, 0, "from");
  detail::require_query_point(to, 1, "to");
  const Border border = border_of(world, Segment{from, to});
  walk(root, from, to, [&](const MaterialCrossing& c) { return border.at(c.t) || report(c); });
}

}  // namespace

std::vector<MaterialCrossing> Landscape::crossings(Point64 from, Point64 to) const {
  std::vector<MaterialCrossing> out;
  walk_world(s_.world, s_.root, from, to, [&](const MaterialCrossing& c) {
    out.push_back(c);
    return true;
  });
  return out;
}

std::optional<MaterialCrossing> Landscape::raycast(Point64 from, Point64 to) const {
  std::optional<MaterialCrossing> hit;
  walk_world(s_.world, s_.root, from, to, [&](const MaterialCrossing& c) {
    if (c.after == kEmpty) return true;  // a back face: leaving into empty space
    hit = c;
    return false;
  });
  return hit;
}

}  // namespace edgeland
