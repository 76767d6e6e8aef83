#include "edgeland/kernel/ray.hpp"

#include <algorithm>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"

namespace edgeland {
namespace {

using W = arith::Checked<Int128>;

formulas::RayEdge<W> parameters(const Ray& ray, const Segment& edge) noexcept {
  return formulas::ray_edge<W>(ray.origin.x, ray.origin.y, ray.dx, ray.dy, edge.a.x, edge.a.y,
                               edge.b.x, edge.b.y);
}

// Sign of cross(direction, edge): < 0 front face, > 0 back face (counter-clockwise ring). The
// den of ray_edge alone (the same products, proven there), not all three of its parts.
Int128 facing(const Ray& ray, const Segment& edge) noexcept {
  return formulas::cross<W>(ray.dx, ray.dy, W(edge.b.x) - W(edge.a.x), W(edge.b.y) - W(edge.a.y)).v;
}

bool culled(RayCulling culling, Int128 face) noexcept {
  switch (culling) {
    case RayCulling::kNoCulling:
      return false;
    case RayCulling::kOriginOutside:
      return face > 0;
    case RayCulling::kOriginInside:
      return face < 0;
  }
  return false;  // Not reached by tests: the switch covers every RayCulling.
}

// An axis-parallel ray cannot meet a segment that lies wholly on one side of its line.
bool off_axis_line(const Ray& ray, const Segment& e) noexcept {
  const Point64 o = ray.origin;
  if (ray.dy == 0 && ray.dx != 0)
    return std::min(e.a.y, e.b.y) > o.y || std::max(e.a.y, e.b.y) < o.y;
  if (ray.dx == 0 && ray.dy != 0)
    return std::min(e.a.x, e.b.x) > o.x || std::max(e.a.x, e.b.x) < o.x;
  return false;
}

// Parallel ray and edge: a contact only when the edge lies on the ray's line; then its nearer
// end, clipped to the origin.
std::optional<Fraction> contact_along(const Ray& ray, const Segment& edge) noexcept {
  const Point64 o = ray.origin, p = edge.a, q = edge.b;
  if (formulas::cross<W>(W(p.x) - W(o.x), W(p.y) - W(o.y), ray.dx, ray.dy) != W(0))
    return std::nullopt;
  const W tp = formulas::ray_projection<W>(o.x, o.y, ray.dx, ray.dy, p.x, p.y);
  const W tq = formulas::ray_projection<W>(o.x, o.y, ray.dx, ray.dy, q.x, q.y);
  if (std::max(tp, tq) < W(0)) return std::nullopt;
  const W dd = formulas::squared_length<W>(ray.dx, ray.dy);
  return Fraction{std::max(W(0), std::min(tp, tq)).v, dd.v};
}

// Where the ray first meets the closed edge p -> q: its smallest t >= 0, if any.
std::optional<Fraction> contact(const Ray& ray, const Segment& edge) noexcept {
  if (ray.dx == 0 && ray.dy == 0) {
    if (on_segment(ray.origin, edge)) return Fraction{0, 1};
    return std::nullopt;
  }
  formulas::RayEdge<W> r = parameters(ray, edge);
  if (r.den == W(0)) return contact_along(ray, edge);
  // o + t d = p + u e with t = t_num / den, u = u_num / den: the hit needs t >= 0, u in [0, 1].
  if (r.den < W(0)) r = {-r.t_num, -r.u_num, -r.den};
  if (r.t_num < W(0) || r.u_num < W(0) || r.den < r.u_num) return std::nullopt;
  return Fraction{r.t_num.v, r.den.v};
}

}  // namespace

std::optional<Fraction> ray_contact(const Ray& ray, const Segment& e) noexcept {
  if (off_axis_line(ray, e)) return std::nullopt;
  return contact(ray, e);
}

RationalPoint ray_point(const Ray& ray, const Fraction& t) noexcept {
  const auto h = formulas::ray_point<W>(ray.origin.x, ray.origin.y, ray.dx, ray.dy, t.num, t.den);
  return RationalPoint{h.x_num.v, h.y_num.v, h.den.v};
}

NearestHit::Offer NearestHit::offer(const Segment& e) noexcept {
  const std::optional<Fraction> t = ray_contact(ray_, e);
  if (!t || (open_ && t->num == 0)) return Offer::kMissed;
  if (found_ && compare(*t, t_) >= 0) return Offer::kFarther;
  found_ = true;
  t_ = *t;
  return Offer::kNearest;
}

std::optional<RayHit> first_hit(const Ray& ray, const Ring& ring, RayCulling culling,
                                RingShape shape) {
  const std::size_t n = ring.size();
  NearestHit nearest(ray);
  std::size_t best_edge = 0;
  bool in_group = false;         // the previous edge was hit
  bool group_collinear = false;  // the current group has an edge along the ray
  bool first_edge_hit = false;   // a group through edge 0 may continue at the ring's end
  int groups = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Segment edge = ring_edge(ring, i);
    const Int128 face = facing(ray, edge);
    const NearestHit::Offer hit =
        culled(culling, face) ? NearestHit::Offer::kMissed : nearest.offer(edge);
    if (hit != NearestHit::Offer::kMissed) {
      if (hit == NearestHit::Offer::kNearest) best_edge = i;
      if (i == 0) first_edge_hit = true;
      if (face == 0) group_collinear = true;
      in_group = true;
      continue;
    }
    if (in_group && shape == RingShape::kConvex && !first_edge_hit) {
      // A group of consecutive hit edges just ended (thesis 2.4.1, 2.4.2).
      ++groups;
      if (culling != RayCulling::kNoCulling || group_collinear || groups == 2) break;
    }
    in_group = false;
    group_collinear = false;
  }
  if (!nearest.found()) return std::nullopt;
  return RayHit{best_edge, nearest.t(), nearest.point()};
}

}  // namespace edgeland
