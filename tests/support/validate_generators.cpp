#include "support/validate_generators.hpp"

#include <algorithm>

namespace edgeland::testing {
namespace {

// Upper half-plane first (angle in [0, pi)), then the lower one.
bool upper_half(Point64 d) { return d.y > 0 || (d.y == 0 && d.x > 0); }

__int128 cross(Point64 a, Point64 b) { return __int128(a.x) * b.y - __int128(a.y) * b.x; }

}  // namespace

Ring star_from_directions(Point64 center, std::vector<Point64> d) {
  auto by_angle = [](Point64 a, Point64 b) {
    if (upper_half(a) != upper_half(b)) return upper_half(a);
    return cross(a, b) > 0;
  };
  std::stable_sort(d.begin(), d.end(), by_angle);
  auto same_direction = [&](Point64 a, Point64 b) { return !by_angle(a, b) && !by_angle(b, a); };
  d.erase(std::unique(d.begin(), d.end(), same_direction), d.end());
  if (d.size() < 3) return {};
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (cross(d[i], d[(i + 1) % d.size()]) <= 0) return {};
  }
  Ring ring;
  for (const Point64 v : d) ring.push_back({center.x + v.x, center.y + v.y});
  return ring;
}

}  // namespace edgeland::testing
