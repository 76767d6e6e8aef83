// Independent checks of triangulations and convex pieces (piece_checks.hpp).
#include "piece_checks.hpp"

#include <algorithm>
#include <set>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/angle.hpp"
#include "edgeland/kernel/convexity.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/validate.hpp"

namespace edgeland::testing {
namespace {

using I128 = __int128;

// Twice the signed area of abc, written here apart from the kernel.
I128 twice_triangle(Point64 a, Point64 b, Point64 c) {
  return I128(b.x - a.x) * (c.y - a.y) - I128(b.y - a.y) * (c.x - a.x);
}

I128 twice_ring_area(const Polygon& ring) {
  I128 sum = 0;
  for (std::size_t i = 1; i + 1 < ring.size(); ++i)
    sum += twice_triangle(ring[0], ring[i], ring[i + 1]);
  return sum;
}

std::string triangle_shape_defect(const Polygon& p, const Triangle& t, std::size_t k) {
  const std::size_t n = p.size();
  if (t.a >= n || t.b >= n || t.c >= n) return "triangle " + std::to_string(k) + ": index >= n";
  if (t.a == t.b || t.b == t.c || t.a == t.c)
    return "triangle " + std::to_string(k) + ": repeated index";
  if (twice_triangle(p[t.a], p[t.b], p[t.c]) <= 0)
    return "triangle " + std::to_string(k) + ": not counter-clockwise with positive area";
  return {};
}

// Whether the open segment p[i] -> p[j] meets no polygon edge (it may touch only at its ends).
bool clear_of_edges(const Polygon& p, std::size_t i, std::size_t j) {
  const Segment d{p[i], p[j]};
  for (std::size_t k = 0; k < p.size(); ++k) {
    const SegmentIntersection x = intersect(d, ring_edge(p, k));
    if (x.relation == SegmentRelation::kDisjoint) continue;
    if (x.relation != SegmentRelation::kTouching) return false;
    if (!is_exactly(x.point, p[i]) && !is_exactly(x.point, p[j])) return false;
  }
  return true;
}

bool inside_diagonal(const Polygon& p, std::size_t i, std::size_t j) {
  const std::size_t n = p.size();
  if (j == (i + 1) % n || i == (j + 1) % n) return true;  // a polygon edge
  const Point64 v = p[i], next = p[(i + 1) % n], prev = p[(i + n - 1) % n], to = p[j];
  const Point64 from_dir{next.x - v.x, next.y - v.y}, to_dir{prev.x - v.x, prev.y - v.y};
  if (!strictly_inside_ccw_sector(from_dir, to_dir, {to.x - v.x, to.y - v.y})) return false;
  return clear_of_edges(p, i, j);
}

std::string piece_shape_defect(const std::set<Point64>& vertices, const Polygon& piece,
                               std::size_t k, std::size_t max_vertices) {
  const std::string name = "piece " + std::to_string(k) + ": ";
  if (piece.size() < 3 || piece.size() > max_vertices)
    return name + std::to_string(piece.size()) + " vertices";
  if (std::set<Point64>(piece.begin(), piece.end()).size() != piece.size())
    return name + "a repeated vertex";
  const std::size_t m = piece.size();
  for (std::size_t i = 0; i < m; ++i) {
    if (vertices.count(piece[i]) == 0) return name + "a vertex not the polygon's";
    if (twice_triangle(piece[i], piece[(i + 1) % m], piece[(i + 2) % m]) <= 0)
      return name + "not a strict left turn at vertex " + std::to_string((i + 1) % m);
  }
  if (!is_convex(piece)) return name + "winds more than once";
  return {};
}

}  // namespace

PolygonSet triangle_polygons(const Polygon& polygon, const std::vector<Triangle>& triangles) {
  PolygonSet out;
  out.reserve(triangles.size());
  for (const Triangle& t : triangles) out.push_back({polygon[t.a], polygon[t.b], polygon[t.c]});
  return out;
}

std::string triangulation_defect(const Polygon& polygon, const std::vector<Triangle>& triangles) {
  if (triangles.size() + 2 != polygon.size())
    return std::to_string(triangles.size()) + " triangles for " + std::to_string(polygon.size()) +
           " vertices";
  I128 sum = 0;
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    if (std::string d = triangle_shape_defect(polygon, triangles[k], k); !d.empty()) return d;
    const Triangle& t = triangles[k];
    sum += twice_triangle(polygon[t.a], polygon[t.b], polygon[t.c]);
  }
  if (sum != twice_ring_area(polygon)) return "the triangles' areas do not sum to the polygon's";
  const ValidationReport report = validate(triangle_polygons(polygon, triangles), 1);
  if (!report.ok()) return "triangles overlap: " + report.violations.front().describe();
  return {};
}

std::string diagonal_defect(const Polygon& polygon, const std::vector<Triangle>& triangles) {
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const Triangle& t = triangles[k];
    const std::uint32_t c[3] = {t.a, t.b, t.c};
    for (int s = 0; s < 3; ++s) {
      if (!inside_diagonal(polygon, c[s], c[(s + 1) % 3]))
        return "triangle " + std::to_string(k) + ": side " + std::to_string(c[s]) + "-" +
               std::to_string(c[(s + 1) % 3]) + " is not inside the polygon";
    }
  }
  return {};
}

std::string convex_pieces_defect(const Polygon& polygon, const std::vector<Polygon>& pieces,
                                 std::size_t max_vertices) {
  const std::set<Point64> vertices(polygon.begin(), polygon.end());
  I128 sum = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    if (std::string d = piece_shape_defect(vertices, pieces[k], k, max_vertices); !d.empty())
      return d;
    sum += twice_ring_area(pieces[k]);
  }
  if (sum != twice_ring_area(polygon)) return "the pieces' areas do not sum to the polygon's";
  const ValidationReport report = validate(pieces, 1);
  if (!report.ok()) return "pieces overlap: " + report.violations.front().describe();
  return {};
}

std::string union_defect(const Polygon& polygon, const PolygonSet& parts) {
  ClipResult x;
  try {
    x = clip(ClipOp::kXor, PolygonSet{polygon}, parts);
  } catch (const InvalidInput& e) {
    return std::string("the clipper rejects the parts: ") + e.what();
  }
  if (!x.polygons.empty())
    return "the union differs from the polygon by " + std::to_string(x.polygons.size()) +
           " piece(s)";
  return {};
}

}  // namespace edgeland::testing
