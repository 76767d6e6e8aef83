// Bounded-exhaustive check of the labeling rule at a shared vertex (thesis 3.4.2, figs. 28a
// and 31) through its public effect.
//
// Configuration: polygons A and B both have a vertex at the origin V. Each is the "wedge" of
// its two edges there: the part of a square around V (half-width 4s for A, 8s for B) inside
// the sector swept counter-clockwise from the outgoing edge's direction to the incoming
// edge's (so the interior is on the left of both edges, as in fig. 28a). The four directions
// run over every primitive integer direction with components in [-2, 2] (16 directions), an
// edge pair being two different directions: 16 * 15 pairs per polygon, 240^2 = 57,600
// configurations, convex and concave (reflex) vertices, shared and reverse-shared edges, and
// straight angles included.
//
// For each edge of A at V, the status w.r.t. B (inside, outside, shared, reverse-shared) is
//   * computed by brute force: an independent winding number (quadrant method, below) of B's
//     ring at two points just left and right of the edge's first unit piece;
//   * read off the library's results: A ∩ B and A − B on A's side of the edge, A ∪ B on the
//     other side (the clipper labels every edge by its local rule at V; no point-in-polygon
//     happens there);
//   * for A's outgoing edge, also given by the thesis's successive_edge_status (fig. 31).
// All three must agree on every configuration. Every crossing here is at an integer point
// (directions divide the square sizes), so nothing is snapped and the results are exact; the
// check asserts that too.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace {

using edgeland::ClipOp;
using edgeland::Point64;
using edgeland::Polygon;
using edgeland::PolygonSet;

constexpr std::int64_t kScale = 16;  // edge pieces are 16 units long per direction step

enum class Status { kInside, kOutside, kShared, kReverseShared };
const char* status_name(Status s) {
  switch (s) {
    case Status::kInside:
      return "inside";
    case Status::kOutside:
      return "outside";
    case Status::kShared:
      return "shared";
    case Status::kReverseShared:
      break;
  }
  return "reverse-shared";
}

std::int64_t cross(Point64 a, Point64 b) { return a.x * b.y - a.y * b.x; }
std::int64_t dot(Point64 a, Point64 b) { return a.x * b.x + a.y * b.y; }
std::int64_t cheb(Point64 d) { return std::max(d.x < 0 ? -d.x : d.x, d.y < 0 ? -d.y : d.y); }
Point64 scaled(Point64 d, std::int64_t k) { return {d.x * k, d.y * k}; }

// The 16 primitive directions with components in [-2, 2].
std::vector<Point64> directions() {
  std::vector<Point64> out;
  for (std::int64_t x = -2; x <= 2; ++x) {
    for (std::int64_t y = -2; y <= 2; ++y) {
      const std::int64_t ax = x < 0 ? -x : x, ay = y < 0 ? -y : y;
      if ((ax | ay) == 0) continue;
      if ((ax % 2 == 0 && ay % 2 == 0)) continue;  // (2 0), (2 2), ...: not primitive
      out.push_back({x, y});
    }
  }
  return out;
}

// Counter-clockwise angle order measured from `from`: true if a comes before b.
bool ccw_before(Point64 from, Point64 a, Point64 b) {
  auto half = [&](Point64 d) {
    const std::int64_t c = cross(from, d);
    return (c > 0 || (c == 0 && dot(from, d) > 0)) ? 0 : 1;
  };
  if (half(a) != half(b)) return half(a) < half(b);
  return cross(a, b) > 0;
}

// The wedge polygon: V, the end of the outgoing edge on the square's boundary, the square's
// corners strictly inside the sector (counter-clockwise), the start of the incoming edge.
Polygon wedge(Point64 out, Point64 in, std::int64_t half_width) {
  Polygon p{{0, 0}, scaled(out, half_width / cheb(out))};
  std::vector<Point64> corners;
  for (const Point64 c : {Point64{half_width, half_width}, Point64{-half_width, half_width},
                          Point64{-half_width, -half_width}, Point64{half_width, -half_width}}) {
    // Strictly inside the sector from `out` counter-clockwise to `in`.
    if (ccw_before(out, c, in) && !(cross(out, c) == 0 && dot(out, c) > 0)) corners.push_back(c);
  }
  std::sort(corners.begin(), corners.end(),
            [&](Point64 a, Point64 b) { return ccw_before(out, a, b); });
  p.insert(p.end(), corners.begin(), corners.end());
  p.push_back(scaled(in, half_width / cheb(in)));
  return p;
}

// Independent winding number (quadrant counting) of a closed ring around p, p not on it.
int quadrant(Point64 p, Point64 v) {
  const std::int64_t dx = v.x - p.x, dy = v.y - p.y;
  if (dx > 0 && dy >= 0) return 0;
  if (dx <= 0 && dy > 0) return 1;
  if (dx < 0 && dy <= 0) return 2;
  return 3;
}
int brute_winding(Point64 p, const Polygon& ring) {
  int turns = 0;  // in quarter turns
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % ring.size()];
    int delta = quadrant(p, b) - quadrant(p, a);
    if (delta == 3) delta = -1;
    if (delta == -3) delta = 1;
    if (delta == 2 || delta == -2) {  // opposite quadrants: the side of p decides
      const std::int64_t c = cross({a.x - p.x, a.y - p.y}, {b.x - p.x, b.y - p.y});
      delta = c > 0 ? 2 : -2;
    }
    turns += delta;
  }
  return turns / 4;
}

Status status_of(bool b_on_a_side, bool b_on_other_side) {
  if (b_on_a_side && b_on_other_side) return Status::kInside;
  if (!b_on_a_side && !b_on_other_side) return Status::kOutside;
  return b_on_a_side ? Status::kShared : Status::kReverseShared;
}

// Thesis fig. 31, successive_edge_status, with "same spot" read as "same direction from V"
// (the edges have different lengths here): e = A's outgoing edge (V -> b), e1 = B's edge
// before V (arriving along -b_in), e2 = B's edge after V.
Status fig31(Point64 a_out, Point64 b_in, Point64 b_out) {
  auto same = [](Point64 u, Point64 v) { return cross(u, v) == 0 && dot(u, v) > 0; };
  if (same(a_out, b_in)) return Status::kReverseShared;  // b is e1's first vertex
  if (same(a_out, b_out)) return Status::kShared;        // b is e2's second vertex
  const bool left_of_e1 = cross(scaled(b_in, -1), a_out) > 0;
  const bool left_of_e2 = cross(b_out, a_out) > 0;
  const bool concave = cross(b_out, b_in) < 0;  // B's interior angle at V exceeds 180 degrees
  if (concave) return (left_of_e1 || left_of_e2) ? Status::kInside : Status::kOutside;
  return (left_of_e1 && left_of_e2) ? Status::kInside : Status::kOutside;
}

bool inside(Point64 p, const PolygonSet& set) {
  return edgeland::locate(p, set) == edgeland::PointLocation::kInside;
}

}  // namespace

int main() {
  const std::vector<Point64> dirs = directions();
  const edgeland::ClipOptions checked{.checked = true};
  std::size_t configurations = 0, edges = 0, failures = 0;
  std::array<std::size_t, 4> seen{};
  auto fail = [&](const std::string& what, const Polygon& a, const Polygon& b) {
    if (++failures <= 10) {
      std::printf("FAIL: %s\n  A = %s\n  B = %s\n", what.c_str(), edgeland::to_wkt(a).c_str(),
                  edgeland::to_wkt(b).c_str());
    }
  };
  for (const Point64 a_in : dirs) {
    for (const Point64 a_out : dirs) {
      if (a_in == a_out) continue;
      const Polygon a = wedge(a_out, a_in, 4 * kScale);
      for (const Point64 b_in : dirs) {
        for (const Point64 b_out : dirs) {
          if (b_in == b_out) continue;
          ++configurations;
          const Polygon b = wedge(b_out, b_in, 8 * kScale);
          if (!edgeland::validate(a).ok() || !edgeland::validate(b).ok()) {
            fail("a wedge is not a valid polygon", a, b);
            continue;
          }
          const PolygonSet sa{a}, sb{b};
          edgeland::ClipResult i, d, u;
          try {
            i = edgeland::clip(ClipOp::kIntersection, sa, sb, checked);
            d = edgeland::clip(ClipOp::kDifference, sa, sb, checked);
            u = edgeland::clip(ClipOp::kUnion, sa, sb, checked);
          } catch (const std::exception& e) {
            fail(std::string("clip threw: ") + e.what(), a, b);
            continue;
          }
          if (i.stats.vertices_snapped + d.stats.vertices_snapped + u.stats.vertices_snapped != 0) {
            fail("a vertex was snapped although every crossing is on the grid", a, b);
          }
          // A's outgoing edge has A's interior on its left; its incoming edge, seen as a ray
          // from V, on its right.
          for (const bool outgoing : {true, false}) {
            ++edges;
            const Point64 r = outgoing ? a_out : a_in;
            const Point64 mid = scaled(r, kScale / 2);
            const Point64 left{mid.x - r.y, mid.y + r.x}, right{mid.x + r.y, mid.y - r.x};
            const Point64 a_side = outgoing ? left : right, other = outgoing ? right : left;
            const Status brute =
                status_of(brute_winding(a_side, b) != 0, brute_winding(other, b) != 0);
            if (brute_winding(a_side, a) != 1 || brute_winding(other, a) != 0) {
              fail("sample points are not on the expected sides of A", a, b);
            }
            const bool lib_a_side = inside(a_side, i.polygons);
            if (lib_a_side == inside(a_side, d.polygons)) {
              fail("A n B and A - B disagree beside A's edge", a, b);
            }
            const Status library = status_of(lib_a_side, inside(other, u.polygons));
            ++seen[static_cast<std::size_t>(brute)];
            if (library != brute) {
              fail(std::string(outgoing ? "outgoing" : "incoming") + " edge: library says " +
                       status_name(library) + ", winding numbers say " + status_name(brute),
                   a, b);
            }
            if (outgoing && fig31(a_out, b_in, b_out) != brute) {
              fail(std::string("fig. 31 says ") + status_name(fig31(a_out, b_in, b_out)) +
                       ", winding numbers say " + status_name(brute),
                   a, b);
            }
          }
        }
      }
    }
  }
  std::printf(
      "labeling at a shared vertex: %zu configurations (%zu directions), %zu edges classified "
      "(inside %zu, outside %zu, shared %zu, reverse-shared %zu), %zu failures\n",
      configurations, dirs.size(), edges, seen[0], seen[1], seen[2], seen[3], failures);
  return failures == 0 ? 0 : 1;
}
