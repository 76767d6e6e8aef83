#include "landscape_oracle.hpp"

#include <algorithm>

#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::test {
namespace {

Rational power_of_two(int negative_exponent) {
  return Rational(BigInt(1), BigInt(1) << negative_exponent);
}

int sign(const Rational& v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }

// Sign of (v - u) x (q - u).
int side(Point64 u, Point64 v, const QPoint& q) {
  return sign(Rational(v.x - u.x) * (q.y - u.y) - Rational(v.y - u.y) * (q.x - u.x));
}

// Winding number of the ring around q; q must not lie on the ring.
int winding(const Ring& ring, const QPoint& q) {
  int w = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point64 u = ring[i], v = ring[(i + 1) % n];
    if (u.y <= q.y) {
      if (v.y > q.y && side(u, v, q) > 0) ++w;
    } else if (v.y <= q.y && side(u, v, q) < 0) {
      --w;
    }
  }
  return w;
}

bool in_box(const Box64& b, const QPoint& q) {
  return b.min.x <= q.x && q.x <= b.max.x && b.min.y <= q.y && q.y <= b.max.y;
}

QPoint along(Point64 a, Point64 b, const Rational& t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

Int128 cross(Point64 u, Point64 v) { return Int128(u.x) * v.y - Int128(u.y) * v.x; }

Rational exact(Int128 v) {
  const bool negative = v < 0;
  const unsigned __int128 u =
      negative ? -static_cast<unsigned __int128>(v) : static_cast<unsigned __int128>(v);
  BigInt r(static_cast<unsigned long long>(u >> 64));
  r <<= 64;
  r += BigInt(static_cast<unsigned long long>(u));
  return Rational(negative ? BigInt(-r) : r);
}

// Parameters t in [0, 1] where the line a -> b meets a vertex or the line of an edge.
std::vector<Rational> candidates(const std::vector<FlatPolygon>& polys, Point64 a, Point64 b) {
  const Point64 d{b.x - a.x, b.y - a.y};
  std::vector<Rational> ts{Rational(0), Rational(1)};
  for (const FlatPolygon& p : polys) {
    for (std::size_t i = 0, n = p.ring.size(); i < n; ++i) {
      const Point64 u = p.ring[i], v = p.ring[(i + 1) % n];
      const Point64 au{u.x - a.x, u.y - a.y}, e{v.x - u.x, v.y - u.y};
      if (cross(d, au) == 0) {
        const Int128 dot = Int128(au.x) * d.x + Int128(au.y) * d.y;
        ts.push_back(exact(dot) / exact(Int128(d.x) * d.x + Int128(d.y) * d.y));
      }
      const Int128 den = cross(d, e);
      if (den != 0) ts.push_back(exact(cross(au, e)) / exact(den));
    }
  }
  std::vector<Rational> kept;
  for (const Rational& t : ts)
    if (t >= 0 && t <= 1) kept.push_back(t);
  std::sort(kept.begin(), kept.end());
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  return kept;
}

}  // namespace

std::string describe(const LandscapeEdit& e) {
  const std::string wkt = to_wkt(e.shape);
  switch (e.kind) {
    case LandscapeEdit::Kind::kCarve:
      return "carve " + wkt;
    case LandscapeEdit::Kind::kFill:
      return "fill " + std::to_string(e.a.value()) + " " + wkt;
    case LandscapeEdit::Kind::kFillEmpty:
      return "fill_empty " + std::to_string(e.a.value()) + " " + wkt;
    case LandscapeEdit::Kind::kReplace:
      return "replace " + std::to_string(e.a.value()) + " " + std::to_string(e.b.value()) + " " +
             wkt;
  }
  return "?";
}

ChangeSet apply(Landscape& l, const LandscapeEdit& e) {
  switch (e.kind) {
    case LandscapeEdit::Kind::kCarve:
      return l.carve(e.shape);
    case LandscapeEdit::Kind::kFill:
      return l.fill(e.shape, e.a);
    case LandscapeEdit::Kind::kFillEmpty:
      return l.fill_empty(e.shape, e.a);
    case LandscapeEdit::Kind::kReplace:
      return l.replace(e.shape, e.a, e.b);
  }
  return {};
}

Material apply_pointwise(const LandscapeEdit& e, Material before, bool inside) {
  if (!inside) return before;
  switch (e.kind) {
    case LandscapeEdit::Kind::kCarve:
      return kEmpty;
    case LandscapeEdit::Kind::kFill:
      return e.a;
    case LandscapeEdit::Kind::kFillEmpty:
      return before == kEmpty ? e.a : before;
    case LandscapeEdit::Kind::kReplace:
      return before == e.a ? e.b : before;
  }
  return before;
}

std::vector<FlatPolygon> flatten(const Landscape& l) {
  std::vector<FlatPolygon> out;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    out.push_back({v.material, *v.polygon, *bounding_box(*v.polygon)});
    return true;
  });
  return out;
}

Material material_brute(const std::vector<FlatPolygon>& polys, const QPoint& q) {
  const Rational eps = power_of_two(100);
  const QPoint moved{q.x + eps, q.y + eps * eps};
  for (const FlatPolygon& p : polys)
    if (in_box(p.box, moved) && winding(p.ring, moved) != 0) return p.material;
  return kEmpty;
}

std::vector<BruteCrossing> profile_brute(const std::vector<FlatPolygon>& polys, Point64 from,
                                         Point64 to) {
  const std::vector<Rational> ts = candidates(polys, from, to);
  const Rational eta = power_of_two(70);
  Material prev = material_brute(polys, along(from, to, -eta));
  std::vector<BruteCrossing> out;
  for (std::size_t k = 0; k < ts.size(); ++k) {
    const Rational next = k + 1 < ts.size() ? (ts[k] + ts[k + 1]) / 2 : Rational(1) + eta;
    const Material after = material_brute(polys, along(from, to, next));
    if (after != prev) out.push_back({ts[k], prev, after});
    prev = after;
  }
  return out;
}

}  // namespace edgeland::test
