#pragma once
// RapidCheck generators of VALID polygon sets and operand pairs for the clipper's properties.
// Every generated set passes the kernel's validate(): members that would break validity are
// dropped (keep_valid), never repaired. The pair generator mixes random shapes with the
// near-degenerate situations the issue asks for (issue 4, "Verification"):
//   one-unit wide slivers and combs (thesis fig. 22), shared and reverse-shared edges, vertex
//   on edge, identical operands, nested operands, touching at a single vertex, collinear
//   overlaps, many edges through one pixel (fans), coordinates at the ends of the range
//   (|c| = kCoordBound), star polygons with many crossings, grid-cell sets sharing edges.
#include <rapidcheck.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "edgeland/kernel/wkt_writer.hpp"
#include "shape_builders.hpp"

namespace edgeland::test {

struct OperandPair {
  std::string scenario;  // which situation the generator built
  PolygonSet a, b;
};

inline void showValue(const OperandPair& p, std::ostream& os) {
  os << p.scenario << "\n  A = " << to_wkt(p.a) << "\n  B = " << to_wkt(p.b);
}

namespace gen {

// Uniform in [lo, hi] whatever RapidCheck's current size (inRange alone shrinks its range
// with the size, down to the single value lo at size 0); shrinks towards lo.
inline rc::Gen<std::int64_t> coord(std::int64_t lo, std::int64_t hi) {
  return rc::gen::resize(rc::kNominalSize, rc::gen::inRange<std::int64_t>(lo, hi + 1));
}

inline rc::Gen<Point64> point_in(Point64 lo, Point64 hi) {
  return rc::gen::exec([=] { return Point64{*coord(lo.x, hi.x), *coord(lo.y, hi.y)}; });
}

// A triangle with vertices in the box, counter-clockwise, non-degenerate.
inline Polygon triangle_in(Point64 lo, Point64 hi) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    Polygon t{*point_in(lo, hi), *point_in(lo, hi), *point_in(lo, hi)};
    if (cross(t[0], t[1], t[2]) != 0) return make_ccw(t);
  }
  return {lo, {hi.x, lo.y}, hi};  // the box's lower-right half (lo < hi in both coordinates)
}

// Convex hull of 3..12 random points within `r` of `c` (a triangle if they are collinear).
inline rc::Gen<Polygon> convex(Point64 c, std::int64_t r) {
  return rc::gen::exec([=] {
    const Point64 lo{c.x - r, c.y - r}, hi{c.x + r, c.y + r};
    const auto pts =
        *rc::gen::container<std::vector<Point64>>(*rc::gen::inRange(3, 13), point_in(lo, hi));
    Polygon h = convex_hull(pts);
    return h.size() >= 3 ? h : triangle_in(lo, hi);
  });
}

// A star polygon: 3..40 random points around c, in angular order (spiky when radii vary).
inline rc::Gen<Polygon> star(Point64 c, std::int64_t r) {
  return rc::gen::exec([=] {
    const Point64 lo{c.x - r, c.y - r}, hi{c.x + r, c.y + r};
    const auto pts =
        *rc::gen::container<std::vector<Point64>>(*rc::gen::inRange(3, 41), point_in(lo, hi));
    Polygon s = star_polygon(c, pts);
    if (s.size() >= 3 && validate(s, 1).ok()) return s;
    Polygon h = convex_hull(pts);
    return h.size() >= 3 ? h : triangle_in(lo, hi);
  });
}

// A one-unit wide slanted strip (parallelogram of height 1 over a long run) or a needle
// triangle of area 1/2: the narrow shapes of thesis fig. 22.
inline rc::Gen<Polygon> sliver(Point64 c, std::int64_t r) {
  return rc::gen::exec([=] {
    const std::int64_t len = *coord(2, std::max<std::int64_t>(2, 2 * r));
    const std::int64_t rise = *coord(-r, r);
    Polygon p;
    if (*rc::gen::arbitrary<bool>())
      p = {{0, 0}, {len, rise}, {len, rise + 1}, {0, 1}};
    else
      p = make_ccw({{0, 0}, {len, rise}, {len - 1, rise + 1}});
    if (twice_area(p) == 0) p = {{0, 0}, {len, rise}, {len, rise + 1}, {0, 1}};
    const Affine place =
        *rc::gen::element(Affine{1, 0, 0, 1, c.x - r, c.y}, Affine{0, -1, 1, 0, c.x, c.y - r},
                          Affine{1, 1, 0, 1, c.x - r, c.y});
    const auto placed = place.apply({p});
    return placed ? placed->front() : p;
  });
}

// An orthogonal comb with one-unit teeth and gaps, optionally sheared (slanted teeth).
inline rc::Gen<Polygon> comb_shape(Point64 c, std::int64_t r) {
  return rc::gen::exec([=] {
    const std::int64_t width = *coord(4, std::max<std::int64_t>(4, 2 * r));
    std::vector<std::pair<std::int64_t, std::int64_t>> teeth;
    const int n = *rc::gen::inRange(1, 8);
    for (int i = 0; i < n; ++i)
      teeth.push_back({2 * *coord(1, width / 2), *coord(1, std::max<std::int64_t>(1, r))});
    const Polygon p = comb(width, teeth);
    const std::int64_t shear = *coord(-2, 2);
    const auto placed = Affine{1, shear, 0, 1, c.x - r, c.y - r}.apply({p});
    return placed && validate(placed->front(), 1).ok() ? placed->front() : p;
  });
}

// A random subset of a k x k grid of square cells of side `size` (members share edges).
inline rc::Gen<PolygonSet> cells(Point64 origin, std::int64_t size, int k) {
  return rc::gen::exec([=] {
    std::vector<std::pair<int, int>> chosen;
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j)
        if (*coord(0, 2) != 0) chosen.push_back({i, j});
    return grid_cells(origin, size, chosen);
  });
}

// A fan of triangles around a vertex near c: up to 12 edges through one point.
inline rc::Gen<PolygonSet> fan_set(Point64 c, std::int64_t r) {
  return rc::gen::exec([=] {
    const auto pts = *rc::gen::container<std::vector<Point64>>(
        *rc::gen::inRange(3, 13), point_in({c.x - r, c.y - r}, {c.x + r, c.y + r}));
    return fan(c, pts);
  });
}

// One shape of any kind within r of c.
inline rc::Gen<Polygon> shape(Point64 c, std::int64_t r) {
  return rc::gen::weightedOneOf<Polygon>(
      {{4, convex(c, r)}, {4, star(c, r)}, {2, sliver(c, r)}, {2, comb_shape(c, r)}});
}

// A valid set within r of c: one shape, several scattered shapes, grid cells or a fan.
inline rc::Gen<PolygonSet> polygon_set(Point64 c, std::int64_t r) {
  auto single = rc::gen::map(shape(c, r), [](Polygon p) { return PolygonSet{std::move(p)}; });
  auto scattered = rc::gen::exec([=] {
    PolygonSet s;
    const int n = *rc::gen::inRange(2, 6);
    for (int i = 0; i < n; ++i) {
      const Point64 at = *point_in({c.x - r, c.y - r}, {c.x + r, c.y + r});
      s.push_back(*shape(at, std::max<std::int64_t>(2, r / 3)));
    }
    return s;
  });
  auto grid = rc::gen::exec([=] {
    const std::int64_t size = *coord(1, std::max<std::int64_t>(1, r / 3));
    return *cells({c.x - r, c.y - r}, size, *rc::gen::inRange(1, 6));
  });
  return rc::gen::map(rc::gen::weightedOneOf<PolygonSet>(
                          {{5, single}, {3, scattered}, {2, grid}, {1, fan_set(c, r)}}),
                      [](const PolygonSet& s) { return keep_valid(s); });
}

// ---- operand pairs ---------------------------------------------------------------------

inline OperandPair pair_of(std::string scenario, const PolygonSet& a, const PolygonSet& b) {
  return {std::move(scenario), keep_valid(a), keep_valid(b)};
}

// A unimodular integer map (det +-1) about a point: rotations by 90 degrees, reflections,
// shears. The image of a valid set is valid (orientation restored by Affine::apply).
inline rc::Gen<Affine> unimodular_about(Point64 p) {
  return rc::gen::exec([=] {
    const auto [m00, m01, m10, m11] = *rc::gen::element(
        std::array<std::int64_t, 4>{0, -1, 1, 0}, std::array<std::int64_t, 4>{-1, 0, 0, -1},
        std::array<std::int64_t, 4>{-1, 0, 0, 1}, std::array<std::int64_t, 4>{0, 1, 1, 0},
        std::array<std::int64_t, 4>{1, 1, 0, 1}, std::array<std::int64_t, 4>{1, 0, -1, 1},
        std::array<std::int64_t, 4>{2, 1, 1, 1});
    Affine t{m00, m01, m10, m11, 0, 0};
    const Point64 image = *t(p);
    t.tx = p.x - image.x;
    t.ty = p.y - image.y;
    return t;
  });
}

// A triangle on edge e of a polygon of the set: apex on the outside gives a reverse-shared
// edge, on the inside a shared (same direction) edge; apex anywhere else near.
inline rc::Gen<OperandPair> edge_triangle_pair(Point64 c, std::int64_t r) {
  return rc::gen::exec([=] {
    const PolygonSet a = *polygon_set(c, r);
    if (a.empty()) return pair_of("edge-triangle", a, a);
    const Polygon& p = *rc::gen::elementOf(a);
    const std::size_t i = static_cast<std::size_t>(*coord(0, std::int64_t(p.size()) - 1));
    const Point64 u = p[i], v = p[(i + 1) % p.size()];
    const std::int64_t s = std::max<std::int64_t>(2, r / 2);
    const Point64 apex = *point_in({u.x - s, u.y - s}, {u.x + s, u.y + s});
    const Int128 side = cross(u, v, apex);
    if (side == 0) return pair_of("edge-triangle", a, PolygonSet{});
    // Outside (right of u->v): the triangle runs v->u, reverse-shared with e.
    const Polygon t = side < 0 ? Polygon{v, u, apex} : Polygon{u, v, apex};
    return pair_of(side < 0 ? "reverse-shared-edge" : "shared-edge", a, PolygonSet{t});
  });
}

// A polygon with a vertex on the interior of an edge of the other operand.
inline rc::Gen<OperandPair> vertex_on_edge_pair(Point64 c, std::int64_t r) {
  return rc::gen::exec([=] {
    const PolygonSet a = *polygon_set(c, r);
    if (a.empty()) return pair_of("vertex-on-edge", a, a);
    const Polygon& p = *rc::gen::elementOf(a);
    const std::size_t i = static_cast<std::size_t>(*coord(0, std::int64_t(p.size()) - 1));
    const Point64 u = p[i], v = p[(i + 1) % p.size()];
    const std::int64_t g = std::gcd(std::abs(v.x - u.x), std::abs(v.y - u.y));
    const std::int64_t k = g > 1 ? *coord(1, g - 1) : 0;
    const Point64 on{u.x + (v.x - u.x) / std::max<std::int64_t>(g, 1) * k,
                     u.y + (v.y - u.y) / std::max<std::int64_t>(g, 1) * k};
    const std::int64_t s = std::max<std::int64_t>(2, r / 2);
    Polygon t{on, *point_in({on.x - s, on.y - s}, {on.x + s, on.y + s}),
              *point_in({on.x - s, on.y - s}, {on.x + s, on.y + s})};
    if (cross(t[0], t[1], t[2]) == 0) return pair_of("vertex-on-edge", a, PolygonSet{});
    return pair_of("vertex-on-edge", a, PolygonSet{make_ccw(t)});
  });
}

// Pairs at the scale r around c (all coordinates within about 2r of c).
inline rc::Gen<OperandPair> local_pair(Point64 c, std::int64_t r) {
  auto independent =
      rc::gen::exec([=] { return pair_of("independent", *polygon_set(c, r), *polygon_set(c, r)); });
  auto identical = rc::gen::exec([=] {
    const PolygonSet a = *polygon_set(c, r);
    return pair_of("identical", a, a);
  });
  auto shifted = rc::gen::exec([=] {
    const PolygonSet a = *polygon_set(c, r);
    const auto b = translation(*coord(-2, 2), *coord(-2, 2)).apply(a);
    return pair_of("shifted", a, b ? *b : a);
  });
  auto transformed = rc::gen::exec([=] {
    const PolygonSet a = *polygon_set(c, r);
    const Point64 about = a.empty() ? c : *rc::gen::elementOf(all_vertices(a));
    const auto b = (*unimodular_about(about)).apply(a);
    return pair_of("transformed-copy", a, b ? *b : PolygonSet{});
  });
  auto vertex_touch = rc::gen::exec([=] {
    // Point reflection about a vertex: for convex A the copy touches A only there.
    const Polygon a = *convex(c, r);
    const Point64 v = *rc::gen::elementOf(a);
    const auto b = Affine{-1, 0, 0, -1, 2 * v.x, 2 * v.y}.apply({a});
    return pair_of("touching-at-vertex", {a}, b ? *b : PolygonSet{});
  });
  auto nested = rc::gen::exec([=] {
    const Polygon outer = *convex(c, r);
    const Point64 inner_c{(outer[0].x + outer[1].x + outer[2].x) / 3,
                          (outer[0].y + outer[1].y + outer[2].y) / 3};
    const PolygonSet inner = *polygon_set(inner_c, std::max<std::int64_t>(2, r / 4));
    return *rc::gen::arbitrary<bool>() ? pair_of("nested", {outer}, inner)
                                       : pair_of("nested", inner, {outer});
  });
  auto grids = rc::gen::exec([=] {
    const std::int64_t size = *coord(1, std::max<std::int64_t>(1, r / 3));
    const int k = *rc::gen::inRange(1, 6);
    const Point64 o{c.x - r, c.y - r};
    const PolygonSet a = *cells(o, size, k);
    const Point64 ob = *rc::gen::element(o, Point64{o.x + size / 2, o.y}, Point64{o.x + 1, o.y + 1},
                                         Point64{o.x + size / 2, o.y + size / 2});
    return pair_of("grid-cells", a, *cells(ob, size, k));
  });
  auto sliver_cross = rc::gen::exec([=] {
    PolygonSet a{*sliver(c, r)};
    PolygonSet b{*rc::gen::oneOf(sliver(c, r), convex(c, r), comb_shape(c, r))};
    return pair_of("sliver-crossing", a, b);
  });
  auto pixel_fans = rc::gen::exec([=] {
    const PolygonSet a = *fan_set(c, r);
    const Point64 c2{c.x + *coord(-1, 1), c.y + *coord(-1, 1)};
    PolygonSet b =
        *rc::gen::arbitrary<bool>()
            ? *fan_set(c2, r)
            : PolygonSet{make_ccw({{c.x - r, c.y - 1}, {c.x + r, c.y + 1}, {c.x, c.y + r}})};
    return pair_of("many-edges-through-one-pixel", a, b);
  });
  auto stars = rc::gen::exec([=] {
    const Point64 c2{c.x + *coord(-2, 2), c.y + *coord(-2, 2)};
    return pair_of("stars", {*star(c, r)}, {*star(c2, r)});
  });
  auto empty = rc::gen::exec([=] {
    const PolygonSet a = *polygon_set(c, r);
    return *rc::gen::arbitrary<bool>() ? pair_of("empty-operand", a, {})
                                       : pair_of("empty-operand", {}, a);
  });
  return rc::gen::weightedOneOf<OperandPair>({{6, independent},
                                              {2, identical},
                                              {3, shifted},
                                              {3, transformed},
                                              {3, edge_triangle_pair(c, r)},
                                              {3, vertex_on_edge_pair(c, r)},
                                              {2, vertex_touch},
                                              {2, nested},
                                              {3, grids},
                                              {3, sliver_cross},
                                              {3, pixel_fans},
                                              {3, stars},
                                              {1, empty}});
}

// Moves a pair to the ends of the coordinate range: translated so that its box touches a
// corner of [-kCoordBound, kCoordBound]^2, or scaled up by a large factor (the crossings
// then have huge denominators), or both. Drops to the original when out of range.
inline rc::Gen<OperandPair> at_range_ends(const OperandPair& p) {
  return rc::gen::exec([p] {
    const PolygonSet both = [&] {
      PolygonSet s = p.a;
      s.insert(s.end(), p.b.begin(), p.b.end());
      return s;
    }();
    const auto box = bounding_box(both);
    if (!box) return p;
    const std::int64_t extent =
        std::max<std::int64_t>(1, std::max(box->max.x - box->min.x, box->max.y - box->min.y));
    Affine t;
    if (*rc::gen::arbitrary<bool>()) {
      const std::int64_t limit = (2 * kCoordBound) / extent;
      const std::int64_t k = *rc::gen::elementOf(std::vector<std::int64_t>{
          std::max<std::int64_t>(1, limit / 3), std::max<std::int64_t>(1, limit / 2),
          std::max<std::int64_t>(1, limit)});
      t = {k, 0, 0, k, 0, 0};
    }
    const auto scaled = t.apply(both);
    if (!scaled) return p;
    const auto sbox = *bounding_box(*scaled);
    const bool right = *rc::gen::arbitrary<bool>(), top = *rc::gen::arbitrary<bool>();
    const std::int64_t dx = right ? kCoordBound - sbox.max.x : -kCoordBound - sbox.min.x;
    const std::int64_t dy = top ? kCoordBound - sbox.max.y : -kCoordBound - sbox.min.y;
    const Affine move{t.m00, 0, 0, t.m11, dx, dy};
    const auto a = move.apply(p.a), b = move.apply(p.b);
    if (!a || !b) return p;
    return pair_of(p.scenario + "@range-end", *a, *b);
  });
}

// Two huge triangles spanning the range: crossings with denominators near 2^64.
inline rc::Gen<OperandPair> huge_triangles() {
  return rc::gen::exec([] {
    const Point64 lo{-kCoordBound, -kCoordBound}, hi{kCoordBound, kCoordBound};
    const Polygon a =
        *rc::gen::arbitrary<bool>()
            ? Polygon{lo, {kCoordBound, -kCoordBound}, {*coord(lo.x, hi.x), kCoordBound}}
            : triangle_in(lo, hi);
    return pair_of("huge-triangles", {a}, {triangle_in(lo, hi)});
  });
}

// The operand pairs of the differential and algebraic properties.
inline rc::Gen<OperandPair> operand_pair() {
  return rc::gen::exec([] {
    const std::int64_t r = *rc::gen::elementOf(std::vector<std::int64_t>{4, 8, 16, 40, 200});
    const Point64 c{*coord(-3, 3), *coord(-3, 3)};
    const int kind = static_cast<int>(*coord(0, 19));
    if (kind == 0) return *huge_triangles();
    OperandPair p = *local_pair(c, r);
    if (kind <= 3) p = *at_range_ends(p);
    return p;
  });
}

}  // namespace gen
}  // namespace edgeland::test
