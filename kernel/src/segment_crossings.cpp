// Crossings of a segment moved by eps (1, eps) with a ring (segment_crossings.hpp): one
// orientation per vertex, a side for every vertex on the line, a crossing wherever an edge's ends
// lie on different sides.
#include "edgeland/kernel/segment_crossings.hpp"

#include <algorithm>

#include "edgeland/kernel/pixel.hpp"

namespace edgeland {
namespace {

int sign(Int128 v) { return (v > 0) - (v < 0); }

// The side of the moved line a vertex on the unmoved line lies on (see the header).
int side_of_points_on_line(const Segment& s) {
  const std::int64_t dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  return dy != 0 ? (dy > 0 ? 1 : -1) : (dx > 0 ? -1 : 1);
}

// t of the vertex v on the line through s: (v - a).d / d.d.
Fraction vertex_parameter(const Segment& s, Point64 v) {
  return {projection(s, v), projection(s, s.b)};
}

// t where the line through s crosses edge p -> q whose ends lie strictly on opposite sides:
// orient(a, p, q) / (orient(a, b, q) - orient(a, b, p)), each orientation below 2^65.
Fraction crossing_parameter(const Segment& s, Point64 p, Point64 q, Int128 op, Int128 oq) {
  Fraction t{orient_det(s.a, p, q), oq - op};
  if (t.den < 0) t = {-t.num, -t.den};
  return t;
}

bool before_start(const Fraction& t) { return t.num < 0; }
bool after_end(const Fraction& t) { return t.num > t.den; }

}  // namespace

RingCrossings segment_crossings(const Segment& s, const Ring& ring, CrossingCulling culling,
                                bool with_inside_before) {
  RingCrossings out;
  const std::size_t n = ring.size();
  if (n < 3 || s.a == s.b) return out;
  const int on_line = side_of_points_on_line(s);
  int entered_before = 0;
  Int128 o_prev = orient_det(s.a, s.b, ring[0]);
  int side_prev = o_prev != 0 ? sign(o_prev) : on_line;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    const Int128 o_next = orient_det(s.a, s.b, ring[j]);
    const int side_next = o_next != 0 ? sign(o_next) : on_line;
    const Int128 op = o_prev;
    const int sp = side_prev;
    o_prev = o_next;
    side_prev = side_next;
    if (sp == side_next) continue;
    const bool entering = sp > 0;  // from the left of the line to its right: a front face
    if (!entering && culling == CrossingCulling::kBackFaces && !with_inside_before) continue;
    SegmentCrossing c;
    c.edge = static_cast<std::uint32_t>(i);
    c.entering = entering;
    if (op == 0 || o_next == 0) {
      c.at_vertex = true;
      c.vertex = static_cast<std::uint32_t>(op == 0 ? i : j);
      c.t = vertex_parameter(s, ring[c.vertex]);
    } else {
      c.t = crossing_parameter(s, ring[i], ring[j], op, o_next);
    }
    if (before_start(c.t)) {
      entered_before += entering ? 1 : -1;
      continue;
    }
    if (after_end(c.t) || (!entering && culling == CrossingCulling::kBackFaces)) continue;
    out.crossings.push_back(c);
  }
  out.inside_before = with_inside_before && entered_before > 0;
  std::sort(out.crossings.begin(), out.crossings.end(),
            [](const SegmentCrossing& x, const SegmentCrossing& y) {
              const int c = compare(x.t, y.t);
              return c != 0 ? c < 0 : x.edge < y.edge;
            });
  return out;
}

RationalPoint crossing_point(const Segment& s, const Ring& ring, const SegmentCrossing& c) {
  if (c.at_vertex) {
    const Point64 v = ring[c.vertex];
    return {v.x, v.y, 1};
  }
  const Segment edge{ring[c.edge], ring[(c.edge + 1) % ring.size()]};
  return *line_intersection(s, edge);
}

}  // namespace edgeland
