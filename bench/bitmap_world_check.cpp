// bitmap_world_check: the bitmap peer must be right before its times mean anything. Checks,
// without any timing (ctest label bench):
//  * paint(): every square of a small world against the kernel's exact half-open point test of
//    its centre (doubled coordinates: centre (2i + 1, 2j + 1), polygon scaled by 2), for n-gons,
//    capsules, concave stars, shapes reaching past the world, and diamonds whose edges pass
//    through square centres;
//  * raycast(): the walk visits |dx| + |dy| + 1 squares, each a 4-neighbour of the one before,
//    from the square of `from` to the square of `to`, each meeting the segment; the hit is the
//    first visited square of another solid material.
// Prints every failure and exits 1 on any.
#include <cmath>
#include <cstdio>
#include <vector>

#include "bitmap_world.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/validate.hpp"
#include "landscape_shapes.hpp"

namespace edgeland::bench {
namespace {

constexpr Box64 kWorld{{-10, -7}, {54, 57}};
int failures = 0;

Polygon doubled(const Polygon& p) {
  Polygon out;
  for (const Point64& v : p) out.push_back({2 * v.x, 2 * v.y});
  return out;
}

// A star with alternating radii (concave), or nothing if its rounding is not valid.
std::vector<Polygon> star(Point64 c, double outer, double inner, std::size_t points) {
  Polygon p;
  for (std::size_t i = 0; i < 2 * points; ++i) {
    const double a = 3.14159265358979323846 * static_cast<double>(i) / static_cast<double>(points);
    const double r = i % 2 == 0 ? outer : inner;
    p.push_back({c.x + std::llround(r * std::cos(a)), c.y + std::llround(r * std::sin(a))});
  }
  if (!validate(PolygonSet{p}, 1).ok()) return {};
  return {p};
}

std::vector<PolygonSet> shapes() {
  std::vector<PolygonSet> out;
  for (double r : {1.0, 2.5, 4.0, 9.0, 17.0, 40.0})
    out.push_back({ngon({20, 23}, r, game_sides(r))});
  out.push_back({ngon_stroke({5, 5}, {31, 12}, 6, 32)});
  out.push_back({ngon_stroke({-12, 40}, {60, 50}, 9, 20)});   // past the world on both sides
  out.push_back({{{10, 10}, {30, 20}, {10, 30}, {20, 20}}});  // concave arrow
  out.push_back({{{20, 0}, {40, 20}, {20, 40}, {0, 20}}});    // edges through square centres
  out.push_back(
      {{{0, 0}, {8, 0}, {8, 8}, {0, 8}}, {{8, 0}, {16, 0}, {16, 8}, {8, 8}}});  // shared edge
  for (std::size_t points : {5, 7, 11})
    for (const Polygon& p : star({24, 26}, 22, 7, points)) out.push_back({p});
  return out;
}

bool inside(const PolygonSet& shape, std::int64_t i, std::int64_t j) {
  for (const Polygon& p : shape)
    if (inside_half_open({2 * i + 1, 2 * j + 1}, doubled(p))) return true;
  return false;
}

void check_paint(const PolygonSet& shape, std::size_t index) {
  BitmapWorld world(kWorld, 1);
  world.paint(shape, 7);
  for (std::int64_t j = kWorld.min.y; j < kWorld.max.y; ++j) {
    for (std::int64_t i = kWorld.min.x; i < kWorld.max.x; ++i) {
      const Material expected = inside(shape, i, j) ? 7 : 1;
      if (world.material_at({i, j}) != expected) {
        std::printf("paint: shape %zu square (%lld %lld): %d, expected %d\n", index,
                    static_cast<long long>(i), static_cast<long long>(j), world.material_at({i, j}),
                    expected);
        ++failures;
      }
    }
  }
}

// The closed unit square (i, j) meets the closed segment.
bool meets(Point64 square, Point64 a, Point64 b) {
  const Box64 box{square, {square.x + 1, square.y + 1}};
  if (box.contains(a) || box.contains(b)) return true;
  const Point64 c[4] = {box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}};
  for (int k = 0; k < 4; ++k)
    if (intersect({a, b}, {c[k], c[(k + 1) % 4]}).relation != SegmentRelation::kDisjoint)
      return true;
  return false;
}

// A hit in a real terrain lies on the segment.
void check_ray(const BitmapWorld& world, Point64 from, Point64 to) {
  const std::optional<BitmapHit> hit = world.raycast(from, to);
  if (hit && !meets(hit->square, from, to)) {
    std::printf("raycast (%lld %lld)->(%lld %lld): hit square (%lld %lld) off the segment\n",
                static_cast<long long>(from.x), static_cast<long long>(from.y),
                static_cast<long long>(to.x), static_cast<long long>(to.y),
                static_cast<long long>(hit->square.x), static_cast<long long>(hit->square.y));
    ++failures;
  }
}

// The walk itself, observed through hits: in a world that is empty except for one square s,
// the ray reports s iff its walk visits s. So the visited set is {s : the ray hits s alone},
// which must have |dx| + |dy| squares besides the start, all meeting the segment, 4-connected.
void check_walk(Point64 from, Point64 to) {
  std::vector<Point64> visited;
  const Box64 area{{std::min(from.x, to.x) - 1, std::min(from.y, to.y) - 1},
                   {std::max(from.x, to.x) + 1, std::max(from.y, to.y) + 1}};
  for (std::int64_t y = area.min.y; y <= area.max.y; ++y) {
    for (std::int64_t x = area.min.x; x <= area.max.x; ++x) {
      if (Point64{x, y} == from) continue;
      BitmapWorld probe(kWorld, 0);
      probe.paint({{{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}}, 3);
      if (probe.raycast(from, to)) visited.push_back({x, y});
    }
  }
  const auto expected =
      static_cast<std::size_t>(std::llabs(to.x - from.x) + std::llabs(to.y - from.y));
  bool ok = visited.size() == expected;
  for (const Point64& s : visited) ok = ok && meets(s, from, to);
  if (!ok) {
    std::printf(
        "walk (%lld %lld)->(%lld %lld): %zu squares visited, expected %zu, or one off the "
        "segment\n",
        static_cast<long long>(from.x), static_cast<long long>(from.y),
        static_cast<long long>(to.x), static_cast<long long>(to.y), visited.size(), expected);
    ++failures;
  }
}

}  // namespace
}  // namespace edgeland::bench

int main() {
  using namespace edgeland;
  using namespace edgeland::bench;
  const std::vector<PolygonSet> all = shapes();
  for (std::size_t i = 0; i < all.size(); ++i) check_paint(all[i], i);
  BitmapWorld terrain(kWorld, 1);
  terrain.carve({ngon({20, 23}, 17, 16)});
  SplitMix64 random(0xD0A);
  for (int k = 0; k < 300; ++k) {
    const Point64 from{20 + static_cast<std::int64_t>(random.next() % 9) - 4,
                       23 + static_cast<std::int64_t>(random.next() % 9) - 4};
    const Point64 to{static_cast<std::int64_t>(random.next() % 50),
                     static_cast<std::int64_t>(random.next() % 50)};
    check_ray(terrain, from, to);
    if (k < 40) check_walk(from, to);
  }
  for (const Point64& to : {Point64{30, 33}, Point64{10, 13}, Point64{30, 13}, Point64{10, 33},
                            Point64{20, 40}, Point64{37, 23}, Point64{20, 23}})
    check_walk({20, 23}, to);  // diagonals through lattice corners, axis-parallel, empty
  std::printf("bitmap_world_check: %d failures\n", failures);
  return failures == 0 ? 0 : 1;
}
