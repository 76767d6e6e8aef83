// The shape builders (shapes.hpp): check the arguments, round the ideal corners (directions
// from shape_trig), add the diamond, then the hull and the cut to the bound (shape_hull).
#include "edgeland/kernel/shapes.hpp"

#include <algorithm>
#include <vector>

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/formulas.hpp"
#include "edgeland/kernel/perimeter.hpp"
#include "shape_hull.hpp"
#include "shape_trig.hpp"

namespace edgeland {
namespace {

using W = arith::Checked<Int128>;
using detail::FixedDirection;

void require_point(Point64 p, std::size_t index, const char* name) {
  if (!in_range(p)) throw CoordinateOutOfRange::argument(Operand::kShape, index, name, p);
}

void require_in(const char* name, std::int64_t value, std::int64_t least, std::int64_t most) {
  if (value < least || value > most) throw ArgumentOutOfRange(name, value, least, most);
}

void require_radius(const char* name, std::int64_t r) { require_in(name, r, 1, kMaxShapeRadius); }

// The direction k / n + phase of a turn (0 <= k < n): one fraction p / q of a turn with
// q = n den <= kMaxTurnParts, reduced to [0, q).
FixedDirection corner_direction(std::int64_t k, std::int64_t n, Turn phase) {
  const Int128 den = phase.den, q = Int128{n} * den;
  const Int128 start = ((phase.num % den) + den) % den;  // in [0, den)
  return detail::direction_of_turn((Int128{k} * den + start * n) % q, q);
}

// The offset (a c - b s, a s + b c) / one of the point (a, b) turned to direction d, rounded.
Point64 turned(std::int64_t a, std::int64_t b, const FixedDirection& d) {
  const W x = formulas::rotated_offset<W>(a, b, d.c, d.s, detail::kFixedOne);
  const W y = formulas::rotated_offset<W>(a, -b, d.s, d.c, detail::kFixedOne);
  return {static_cast<std::int64_t>(x.v), static_cast<std::int64_t>(y.v)};
}

Point64 plus(Point64 c, Point64 offset) { return {c.x + offset.x, c.y + offset.y}; }

// The least shape of every builder: the four points at distance 1 around c.
void add_diamond(std::vector<Point64>& points, Point64 c) {
  for (const Point64 d : {Point64{1, 0}, Point64{0, 1}, Point64{-1, 0}, Point64{0, -1}})
    points.push_back(plus(c, d));
}

// The offsets of the regular polygon's corners around the origin.
std::vector<Point64> corner_offsets(std::int64_t radius, std::int64_t sides, Turn phase) {
  std::vector<Point64> out;
  out.reserve(static_cast<std::size_t>(sides));
  for (std::int64_t k = 0; k < sides; ++k)
    out.push_back(turned(radius, 0, corner_direction(k, sides, phase)));
  return out;
}

// The triangle (c, c +- (1, 0), c +- (0, 1)) inside the bound, counter-clockwise: the diamond's
// least part that the bound never cuts (c is in range, so one neighbour per axis is too).
Polygon corner_triangle(Point64 c) {
  const Point64 east{c.x < kCoordBound ? c.x + 1 : c.x - 1, c.y};
  const Point64 north{c.x, c.y < kCoordBound ? c.y + 1 : c.y - 1};
  const bool counter_clockwise = (east.x - c.x) * (north.y - c.y) > 0;
  return counter_clockwise ? Polygon{c, east, north} : Polygon{c, north, east};
}

// The hull of the points, cut to the bound if it reaches past it (then hulled once more, which
// starts it at the lowest of its leftmost corners again). The hull alone always has area (the
// diamond is among the points); the corner triangle at `anchor` is a guard for a cut that
// would leave none, kept because no proof shows it cannot: not reached by tests, nor by 9
// million small shapes of every builder on and next to the bound's corners.
Polygon finish(std::vector<Point64> points, Point64 anchor) {
  Polygon shape = detail::convex_hull(std::move(points));
  if (std::all_of(shape.begin(), shape.end(), [](Point64 p) { return in_range(p); })) return shape;
  shape = detail::convex_hull(detail::cut_to_bound(std::move(shape)));
  return shape.size() >= 3 ? shape : corner_triangle(anchor);
}

}  // namespace

Polygon regular_polygon(Point64 center, std::int64_t radius, std::int64_t sides, Turn phase) {
  require_point(center, 0, "center");
  require_radius("radius", radius);
  require_in("sides", sides, 3, kMaxShapeSides);
  require_in("phase denominator", phase.den, 1, kMaxTurnDenominator);
  std::vector<Point64> points;
  for (const Point64 o : corner_offsets(radius, sides, phase)) points.push_back(plus(center, o));
  add_diamond(points, center);
  return finish(std::move(points), center);
}

std::int64_t circle_sides(std::int64_t radius) {
  require_radius("radius", radius);
  const auto square = static_cast<UInt128>(10 * radius);
  auto root = static_cast<std::int64_t>(isqrt(square));
  if (static_cast<UInt128>(root) * static_cast<UInt128>(root) < square) ++root;
  const std::int64_t sides = (root + 7) / 8 * 8;
  return sides < kMaxCircleSides ? sides : kMaxCircleSides;
}

Polygon circle(Point64 center, std::int64_t radius) {
  require_point(center, 0, "center");
  return regular_polygon(center, radius, circle_sides(radius));
}

Polygon capsule(Point64 a, Point64 b, std::int64_t radius) {
  require_point(a, 0, "a");
  require_point(b, 1, "b");
  const std::vector<Point64> offsets = corner_offsets(radius, circle_sides(radius), Turn{});
  std::vector<Point64> points;
  for (const Point64 end : {a, b}) {
    for (const Point64 o : offsets) points.push_back(plus(end, o));
    add_diamond(points, end);
  }
  return finish(std::move(points), a);
}

Polygon box_shape(const Box64& box) {
  require_point(box.min, 0, "box min");
  require_point(box.max, 1, "box max");
  require_in("box width", box.max.x - box.min.x, 1, 2 * kCoordBound);
  require_in("box height", box.max.y - box.min.y, 1, 2 * kCoordBound);
  return {box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}};
}

Polygon rotated_box(Point64 center, std::int64_t half_width, std::int64_t half_height, Turn angle) {
  require_point(center, 0, "center");
  require_radius("half_width", half_width);
  require_radius("half_height", half_height);
  require_in("angle denominator", angle.den, 1, kMaxTurnDenominator);
  const FixedDirection d = corner_direction(0, 1, angle);
  std::vector<Point64> points;
  for (const std::int64_t sx : {1, -1})
    for (const std::int64_t sy : {1, -1})
      points.push_back(plus(center, turned(sx * half_width, sy * half_height, d)));
  add_diamond(points, center);
  return finish(std::move(points), center);
}

}  // namespace edgeland
