#include "surface_oracle.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace edgeland::test {
namespace {

struct DirectedEdge {
  Point64 a, b;
  Material material;
};

OracleLine line_through(Point64 a, Point64 b) {
  std::int64_t dx = b.x - a.x, dy = b.y - a.y;
  const std::int64_t g = std::gcd(dx, dy);
  dx /= g;
  dy /= g;
  if (dx < 0 || (dx == 0 && dy < 0)) dx = -dx, dy = -dy;
  return {dx, dy, Int128(dx) * a.y - Int128(dy) * a.x};
}

std::int64_t position(const OracleLine& l, Point64 p) { return l.dx != 0 ? p.x : p.y; }

// Runs of one direction with the parts covered by `cover` (any direction, any material) removed.
std::vector<Run> minus(const std::vector<Run>& runs, const std::vector<Run>& cover) {
  std::vector<Run> out;
  for (const Run& r : runs) {
    std::vector<Run> pieces{r};
    for (const Run& c : cover) {
      std::vector<Run> next;
      for (const Run& p : pieces) {
        if (c.hi <= p.lo || c.lo >= p.hi) {
          next.push_back(p);
          continue;
        }
        if (p.lo < c.lo) next.push_back({p.lo, c.lo, p.forward, p.material});
        if (c.hi < p.hi) next.push_back({c.hi, p.hi, p.forward, p.material});
      }
      pieces = std::move(next);
    }
    out.insert(out.end(), pieces.begin(), pieces.end());
  }
  return out;
}

// Sorted, with touching runs of one direction and material merged.
std::vector<Run> normalized(std::vector<Run> runs) {
  std::sort(runs.begin(), runs.end(), [](const Run& l, const Run& r) {
    return std::tie(l.forward, l.lo) < std::tie(r.forward, r.lo);
  });
  std::vector<Run> out;
  for (const Run& r : runs) {
    if (!out.empty() && out.back().forward == r.forward && out.back().material == r.material &&
        out.back().hi == r.lo)
      out.back().hi = r.hi;
    else
      out.push_back(r);
  }
  return out;
}

void add(SurfaceMap& map, Point64 a, Point64 b, Material m) {
  const OracleLine l = line_through(a, b);
  const std::int64_t pa = position(l, a), pb = position(l, b);
  map[l].push_back({std::min(pa, pb), std::max(pa, pb), pa < pb, m});
}

bool on_border(const Box64& w, Point64 a, Point64 b) {
  return (a.x == b.x && (a.x == w.min.x || a.x == w.max.x)) ||
         (a.y == b.y && (a.y == w.min.y || a.y == w.max.y));
}

// The world's border, clockwise (outside on the left), as four edges.
std::vector<DirectedEdge> border_clockwise(const Box64& w) {
  const Point64 p0 = w.min, p1{w.max.x, w.min.y}, p2 = w.max, p3{w.min.x, w.max.y};
  return {{p1, p0, kEmpty}, {p0, p3, kEmpty}, {p3, p2, kEmpty}, {p2, p1, kEmpty}};
}

}  // namespace

SurfaceMap surface_brute(const Landscape& world, const SurfaceOptions& options) {
  SurfaceMap all, border_solid;
  world.polygons_in(world.world(), [&](const PolygonView& v) {
    if (v.material == kEmpty || !options.materials.solid[v.material.value()]) return true;
    const Polygon& r = *v.polygon;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Point64 a = r[i], b = r[(i + 1) % r.size()];
      add(on_border(world.world(), a, b) ? border_solid : all, a, b, v.material);
    }
    return true;
  });
  SurfaceMap out;
  for (auto& [line, runs] : all) {
    std::vector<Run> fwd, bwd;
    for (const Run& r : runs) (r.forward ? fwd : bwd).push_back(r);
    std::vector<Run> surface = minus(fwd, bwd), back = minus(bwd, fwd);
    surface.insert(surface.end(), back.begin(), back.end());
    if (!surface.empty()) out[line] = normalized(surface);
  }
  if (options.border_wall) {
    for (const DirectedEdge& e : border_clockwise(world.world())) {
      SurfaceMap wall;
      add(wall, e.a, e.b, kEmpty);
      for (auto& [line, runs] : wall) {
        const auto solid = border_solid.find(line);
        std::vector<Run> left = solid == border_solid.end() ? runs : minus(runs, solid->second);
        auto& target = out[line];
        target.insert(target.end(), left.begin(), left.end());
        target = normalized(target);
        if (target.empty()) out.erase(line);
      }
    }
  }
  return out;
}

SurfaceMap surface_of(const std::vector<SurfaceChain>& chains) {
  SurfaceMap out;
  for (const SurfaceChain& c : chains) {
    const std::size_t n = c.points.size(), segments = c.closed ? n : n - 1;
    for (std::size_t i = 0; i < segments; ++i)
      add(out, c.points[i], c.points[(i + 1) % n], c.materials[i]);
  }
  for (auto& [line, runs] : out) runs = normalized(runs);
  return out;
}

std::string surface_difference(const SurfaceMap& expected, const SurfaceMap& actual) {
  std::ostringstream os;
  auto describe = [&](const OracleLine& l, const std::vector<Run>& runs) {
    os << "line d=(" << l.dx << ' ' << l.dy << ") offset " << to_string(l.offset) << ':';
    for (const Run& r : runs)
      os << " [" << r.lo << ',' << r.hi << (r.forward ? " +" : " -") << " m"
         << int(r.material.value()) << ']';
  };
  for (const auto& [line, runs] : expected) {
    const auto it = actual.find(line);
    if (it != actual.end() && it->second == runs) continue;
    os << "expected ";
    describe(line, runs);
    os << "\n  actual ";
    if (it == actual.end())
      os << "nothing";
    else
      describe(line, it->second);
    return os.str();
  }
  for (const auto& [line, runs] : actual)
    if (!expected.count(line)) {
      os << "unexpected ";
      describe(line, runs);
      return os.str();
    }
  return "";
}

}  // namespace edgeland::test
