#include "edgeland/kernel/ray.hpp"

#include <algorithm>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"

namespace edgeland {
namespace {

using W = arith::Checked<Int128>;

// Sign of cross(direction, edge): < 0 front face, > 0 back face (counter-clockwise ring).
Int128 facing(const Ray& ray, const Segment& edge) noexcept {
  return formulas::cross<W>(ray.dx, ray.dy, W(edge.b.x) - W(edge.a.x), W(edge.b.y) - W(edge.a.y))
      .v;
}

bool culled(RayCulling culling, Int128 face) noexcept {
  switch (culling) {
    case RayCulling::kNone:
      return false;
    case RayCulling::kOriginOutside:
      return face > 0;
    case RayCulling::kOriginInside:
      return face < 0;
  }
  return false;
}

// Where the ray first meets the closed edge p -> q: its smallest t >= 0, if any.
// den_raw is cross(direction, edge), already computed for culling.
std::optional<Fraction> contact(const Ray& ray, const Segment& edge, Int128 den_raw) noexcept {
  const Point64 o = ray.origin, p = edge.a, q = edge.b;
  if (ray.dx == 0 && ray.dy == 0) {
    if (on_segment(o, edge)) return Fraction{0, 1};
    return std::nullopt;
  }
  const W wx = W(p.x) - W(o.x), wy = W(p.y) - W(o.y);
  if (den_raw != 0) {
    // Solve o + t d = p + u e:  t = cross(w, e) / cross(d, e),  u = cross(w, d) / cross(d, e).
    W t = formulas::orient<W>(o.x, o.y, p.x, p.y, q.x, q.y);  // == cross(w, e)
    W u = formulas::cross<W>(wx, wy, ray.dx, ray.dy);
    W den = den_raw;
    if (den < W(0)) {
      t = -t;
      u = -u;
      den = -den;
    }
    if (t < W(0) || u < W(0) || den < u) return std::nullopt;
    return Fraction{t.v, den.v};
  }
  // Parallel: a contact only when the edge lies on the ray's line; then its nearer end,
  // clipped to the origin. Parameters along the line are dot(x - o, d) / dot(d, d).
  if (formulas::cross<W>(wx, wy, ray.dx, ray.dy) != W(0)) return std::nullopt;
  const W tp = formulas::dot_from<W>(o.x, o.y, W(o.x) + W(ray.dx), W(o.y) + W(ray.dy), p.x, p.y);
  const W tq = formulas::dot_from<W>(o.x, o.y, W(o.x) + W(ray.dx), W(o.y) + W(ray.dy), q.x, q.y);
  if (std::max(tp, tq) < W(0)) return std::nullopt;
  const W dd = formulas::dot_from<W>(0, 0, ray.dx, ray.dy, ray.dx, ray.dy);  // dot(d, d)
  return Fraction{std::max(W(0), std::min(tp, tq)).v, dd.v};
}

RationalPoint point_at(const Ray& ray, const Fraction& t) noexcept {
  const W x = W(ray.origin.x) * W(t.den) + W(t.num) * W(ray.dx);
  const W y = W(ray.origin.y) * W(t.den) + W(t.num) * W(ray.dy);
  return RationalPoint{x.v, y.v, t.den};
}

}  // namespace

std::optional<RayHit> first_hit(const Ray& ray, const Ring& ring, RayCulling culling,
                                RingShape shape) {
  const std::size_t n = ring.size();
  std::optional<RayHit> best;
  bool in_group = false;         // the previous edge was hit
  bool group_collinear = false;  // the current group has an edge along the ray
  bool first_edge_hit = false;   // a group through edge 0 may continue at the ring's end
  int groups = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Segment edge = ring_edge(ring, i);
    const Int128 face = facing(ray, edge);
    std::optional<Fraction> t;
    if (!culled(culling, face)) t = contact(ray, edge, face);
    if (t) {
      if (!best || compare(*t, best->t) < 0) best = RayHit{i, *t, {}};
      if (i == 0) first_edge_hit = true;
      if (face == 0) group_collinear = true;
      in_group = true;
      continue;
    }
    if (in_group && shape == RingShape::kConvex && !first_edge_hit) {
      // A group of consecutive hit edges just ended (thesis 2.4.1, 2.4.2).
      ++groups;
      if (culling != RayCulling::kNone || group_collinear || groups == 2) break;
    }
    in_group = false;
    group_collinear = false;
  }
  if (best) best->point = point_at(ray, best->t);
  return best;
}

}  // namespace edgeland
