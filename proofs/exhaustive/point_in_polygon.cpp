// Bounded-exhaustive check of point-in-polygon (point_in_polygon.hpp, thesis 2.5): for every
// strictly simple polygon of 3 to 5 vertices on a 4x4 grid, in both orientations, and every
// point of the grid around it, locate() and winding_number() agree with an independent
// winding-number reference; locate_convex() (thesis 2.5.2) does too on the convex
// counter-clockwise ones. The polygon is scaled by 2 (coordinates 0, 2, 4, 6) and the
// query points are all of [-1, 7]^2, so they include every vertex, every edge midpoint,
// every cell centre and points outside on all sides: the ray-through-vertex and
// ray-along-edge cases of thesis figures 13 and 15 all occur.
#include "edgeland/kernel/point_in_polygon.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "case_log.hpp"
#include "grids.hpp"
#include "segment_reference.hpp"

namespace edgeland::exhaustive {
namespace {

std::int64_t cross(Point64 o, Point64 a, Point64 b) {  // exact: coordinates are tiny
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Whether p is on the closed segment ab: collinear and between the ends along ab.
bool on_edge(Point64 p, Point64 a, Point64 b) {
  if (cross(a, b, p) != 0) return false;
  const std::int64_t along = (p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y);
  const std::int64_t length2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
  return 0 <= along && along <= length2;
}

// Quadrant of v around p (p != v), counter-clockwise from the positive x axis.
int quadrant(Point64 p, Point64 v) {
  const std::int64_t dx = v.x - p.x, dy = v.y - p.y;
  if (dx > 0 && dy >= 0) return 0;
  if (dx <= 0 && dy > 0) return 1;
  if (dx < 0 && dy <= 0) return 2;
  return 3;
}

// The winding number of the ring around p (p off the boundary) by the quadrant method: the
// total angle swept by the vertex as seen from p, counted in quarter turns. A step to the
// opposite quadrant passes p on its left or its right, which the side of p decides.
int reference_winding(Point64 p, const Ring& ring) {
  int quarters = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % ring.size()];
    const int step = (quadrant(p, b) - quadrant(p, a) + 4) % 4;
    if (step == 1) quarters += 1;
    if (step == 3) quarters -= 1;
    if (step == 2) quarters += cross(p, a, b) > 0 ? 2 : -2;
  }
  return quarters / 4;
}

bool reference_on_boundary(Point64 p, const Ring& ring) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (on_edge(p, ring[i], ring[(i + 1) % ring.size()])) return true;
  }
  return false;
}

// Strictly simple: adjacent edges share only their common vertex, others share nothing
// (decided by the rational segment reference).
bool strictly_simple(const Ring& ring) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const Segment ei{ring[i], ring[(i + 1) % n]}, ej{ring[j], ring[(j + 1) % n]};
      const ReferenceIntersection r = reference_intersect(ei, ej);
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (!adjacent && r.relation != SegmentRelation::kDisjoint) return false;
      if (adjacent && r.relation != SegmentRelation::kTouching) return false;
    }
  }
  return true;
}

// Counter-clockwise and convex: every turn is left or straight, and the area is positive.
bool convex_ccw(const Ring& ring) {
  std::int64_t twice_area = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % ring.size()], c = ring[(i + 2) % ring.size()];
    if (cross(a, b, c) < 0) return false;
    twice_area += a.x * b.y - a.y * b.x;
  }
  return twice_area > 0;
}

PointLocation reference_locate(Point64 p, const Ring& ring) {
  if (reference_on_boundary(p, ring)) return PointLocation::kOnBoundary;
  return reference_winding(p, ring) != 0 ? PointLocation::kInside : PointLocation::kOutside;
}

std::string describe(Point64 p, const Ring& ring) {
  std::string s = str(p) + " in";
  for (Point64 v : ring) s += " " + str(v);
  return s;
}

// Calls visit(ring) for every sequence of k distinct grid points whose first point has the
// smallest index (one representative per rotation; both directions are kept).
template <class Visit>
void each_ring(const std::vector<Point64>& pts, std::size_t k, Visit&& visit) {
  std::array<std::size_t, 5> idx{};
  Ring ring(k);
  auto extend = [&](auto&& self, std::size_t depth) -> void {
    if (depth == k) {
      visit(ring);
      return;
    }
    for (std::size_t i = depth == 0 ? 0 : idx[0] + 1; i < pts.size(); ++i) {
      bool used = false;
      for (std::size_t d = 1; d < depth; ++d) used = used || idx[d] == i;
      if (used) continue;
      idx[depth] = i;
      ring[depth] = pts[i];
      self(self, depth + 1);
    }
  };
  extend(extend, 0);
}

}  // namespace
}  // namespace edgeland::exhaustive

int main() {
  using namespace edgeland;
  using namespace edgeland::exhaustive;
  const std::vector<Point64> vertices = grid(4, 0, 2);
  const std::vector<Point64> queries = grid(9, -1, 1);
  CaseLog loc("locate == reference (boundary, else winding != 0)");
  CaseLog wind("winding_number == quadrant winding number (off boundary)");
  CaseLog convex("locate_convex == reference (convex ccw polygons)");
  std::uint64_t rings = 0, simple = 0, convex_rings = 0;
  std::array<std::uint64_t, 3> answers{};  // reference answers: outside, inside, on boundary
  for (std::size_t k = 3; k <= 5; ++k) {
    each_ring(vertices, k, [&](const Ring& ring) {
      ++rings;
      if (!strictly_simple(ring)) return;
      ++simple;
      const bool is_convex = convex_ccw(ring);
      convex_rings += is_convex;
      for (Point64 p : queries) {
        const PointLocation want = reference_locate(p, ring);
        ++answers[static_cast<std::size_t>(want)];
        loc.expect(locate(p, ring) == want, [&] { return describe(p, ring); });
        if (want != PointLocation::kOnBoundary) {
          wind.expect(winding_number(p, ring) == reference_winding(p, ring),
                      [&] { return describe(p, ring); });
        }
        if (is_convex) {
          convex.expect(locate_convex(p, ring) == want, [&] { return describe(p, ring); });
        }
      }
    });
  }
  std::printf(
      "4x4 grid (scaled by 2), 3..5 vertices: %llu rings enumerated, %llu strictly simple "
      "(%llu convex ccw), %zu query points each\n",
      static_cast<unsigned long long>(rings), static_cast<unsigned long long>(simple),
      static_cast<unsigned long long>(convex_rings), queries.size());
  std::printf("reference answers: %llu outside, %llu inside, %llu on the boundary\n",
              static_cast<unsigned long long>(answers[0]),
              static_cast<unsigned long long>(answers[1]),
              static_cast<unsigned long long>(answers[2]));
  const bool a = loc.report(), b = wind.report(), c = convex.report();
  return a && b && c ? 0 : 1;
}
