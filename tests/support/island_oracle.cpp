#include "island_oracle.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace edgeland::test {
namespace {

struct Edge {
  std::size_t polygon;
  std::int64_t lo, hi;  // along the line (x, or y when vertical)
  bool forward;
};

struct Line {
  std::int64_t dx, dy;
  Int128 offset;
  friend bool operator<(const Line& l, const Line& r) {
    return std::tie(l.dx, l.dy, l.offset) < std::tie(r.dx, r.dy, r.offset);
  }
};

std::size_t root(std::vector<std::size_t>& parent, std::size_t x) {
  while (parent[x] != x) x = parent[x];
  return x;
}

}  // namespace

std::set<IdSet> islands_brute(const Landscape& world, const PhysicsMaterials& materials) {
  std::vector<PolygonId> ids;
  std::vector<bool> held;
  std::map<Line, std::vector<Edge>> lines;
  const Box64 w = world.world();
  world.polygons_in(w, [&](const PolygonView& v) {
    if (v.material == kEmpty || !materials.solid[v.material.value()]) return true;
    const std::size_t index = ids.size();
    ids.push_back(v.id);
    held.push_back(materials.anchored[v.material.value()]);
    const Polygon& r = *v.polygon;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Point64 a = r[i], b = r[(i + 1) % r.size()];
      if ((a.x == b.x && (a.x == w.min.x || a.x == w.max.x)) ||
          (a.y == b.y && (a.y == w.min.y || a.y == w.max.y)))
        held[index] = true;
      std::int64_t dx = b.x - a.x, dy = b.y - a.y;
      const std::int64_t g = std::gcd(dx, dy);
      dx /= g, dy /= g;
      if (dx < 0 || (dx == 0 && dy < 0)) dx = -dx, dy = -dy;
      const std::int64_t pa = dx != 0 ? a.x : a.y, pb = dx != 0 ? b.x : b.y;
      lines[{dx, dy, Int128(dx) * a.y - Int128(dy) * a.x}].push_back(
          {index, std::min(pa, pb), std::max(pa, pb), pa < pb});
    }
    return true;
  });
  std::vector<std::size_t> parent(ids.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [line, edges] : lines)
    for (const Edge& e : edges)
      for (const Edge& f : edges)
        if (e.forward && !f.forward && std::min(e.hi, f.hi) > std::max(e.lo, f.lo))
          parent[root(parent, e.polygon)] = root(parent, f.polygon);
  std::map<std::size_t, IdSet> components;
  std::map<std::size_t, bool> component_held;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const std::size_t r = root(parent, i);
    components[r].push_back(ids[i]);
    component_held[r] = component_held[r] || held[i];
  }
  std::set<IdSet> out;
  for (auto& [r, set] : components) {
    if (component_held[r]) continue;
    std::sort(set.begin(), set.end());
    out.insert(set);
  }
  return out;
}

}  // namespace edgeland::test
