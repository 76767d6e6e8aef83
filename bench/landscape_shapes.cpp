#include "landscape_shapes.hpp"

#include <algorithm>
#include <cmath>

#include "edgeland/kernel/validate.hpp"

namespace edgeland::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::int64_t cross(Point64 o, Point64 a, Point64 b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain, collinear points dropped: a strictly convex CCW polygon.
Polygon convex_hull(std::vector<Point64> points) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  Polygon hull(2 * points.size());
  std::size_t k = 0;
  for (const Point64& p : points) {  // lower hull
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper hull
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

void add_ngon_points(std::vector<Point64>& out, Point64 c, double radius, std::size_t sides) {
  for (std::size_t i = 0; i < sides; ++i) {
    const double angle = 2.0 * kPi * static_cast<double>(i) / static_cast<double>(sides);
    out.push_back({c.x + std::llround(radius * std::cos(angle)),
                   c.y + std::llround(radius * std::sin(angle))});
  }
}

}  // namespace

Polygon ngon(Point64 centre, double radius, std::size_t sides) {
  std::vector<Point64> points;
  add_ngon_points(points, centre, radius, sides);
  Polygon polygon = points;
  polygon.erase(std::unique(polygon.begin(), polygon.end()), polygon.end());
  while (polygon.size() > 1 && polygon.front() == polygon.back()) polygon.pop_back();
  if (validate(PolygonSet{polygon}, 1).ok()) return polygon;
  return convex_hull(std::move(points));
}

std::size_t game_sides(double radius) {
  const auto sides = static_cast<std::size_t>(std::llround(2.0 * kPi * radius / 8.0));
  return std::clamp<std::size_t>(sides, 16, 512);
}

Polygon ngon_stroke(Point64 a, Point64 b, double radius, std::size_t sides) {
  std::vector<Point64> points;
  add_ngon_points(points, a, radius, sides);
  add_ngon_points(points, b, radius, sides);
  return convex_hull(std::move(points));
}

std::vector<Point64> random_points(std::uint64_t seed, std::size_t count, const Box64& box) {
  SplitMix64 random(seed);
  const auto w = static_cast<std::uint64_t>(box.max.x - box.min.x) + 1;
  const auto h = static_cast<std::uint64_t>(box.max.y - box.min.y) + 1;
  std::vector<Point64> out(count);
  for (Point64& p : out) {
    p.x = box.min.x + static_cast<std::int64_t>(random.next() % w);
    p.y = box.min.y + static_cast<std::int64_t>(random.next() % h);
  }
  return out;
}

std::vector<Point64> random_walk(std::uint64_t seed, std::size_t count, double step,
                                 const Box64& box) {
  SplitMix64 random(seed);
  double x = static_cast<double>(box.min.x + box.max.x) / 2;
  double y = static_cast<double>(box.min.y + box.max.y) / 2;
  double heading = 2.0 * kPi * unit_draw(random);
  std::vector<Point64> out{{std::llround(x), std::llround(y)}};
  while (out.size() <= count) {
    heading += (unit_draw(random) - 0.5) * (kPi / 9.0);
    const double nx = x + step * std::cos(heading), ny = y + step * std::sin(heading);
    if (nx < static_cast<double>(box.min.x) || nx > static_cast<double>(box.max.x) ||
        ny < static_cast<double>(box.min.y) || ny > static_cast<double>(box.max.y)) {
      heading += kPi;  // back into the box
      continue;
    }
    x = nx;
    y = ny;
    out.push_back({std::llround(x), std::llround(y)});
  }
  return out;
}

std::vector<Polygon> caves(std::uint64_t seed, std::size_t count, const Box64& box) {
  SplitMix64 random(seed ^ 0xCA7E5);
  std::vector<Polygon> out;
  for (const Point64& c : random_points(seed, count, box)) {
    const double radius = 24.0 + 136.0 * unit_draw(random);
    out.push_back(ngon(c, radius, game_sides(radius)));
  }
  return out;
}

Box64 inset(const Box64& box, std::int64_t margin) {
  return {{box.min.x + margin, box.min.y + margin}, {box.max.x - margin, box.max.y - margin}};
}

std::vector<ValidSet> as_shapes(const std::vector<Polygon>& polygons) {
  std::vector<ValidSet> out;
  out.reserve(polygons.size());
  for (const Polygon& p : polygons) out.emplace_back(PolygonSet{p}, Operand::kClip);
  return out;
}

std::vector<ValidSet> explosions(std::uint64_t seed, std::size_t count, const Box64& world) {
  std::vector<Polygon> polygons;
  for (const Point64& c : random_points(seed, count, world)) polygons.push_back(ngon(c, 40, 32));
  return as_shapes(polygons);
}

std::vector<ValidSet> digger_strokes(std::uint64_t seed, std::size_t count, const Box64& world) {
  const std::vector<Point64> walk = random_walk(seed, count, 10.0, inset(world, 64));
  std::vector<Polygon> polygons;
  for (std::size_t i = 0; i < count; ++i)
    polygons.push_back(ngon_stroke(walk[i], walk[i + 1], 20, 32));
  return as_shapes(polygons);
}

}  // namespace edgeland::bench
