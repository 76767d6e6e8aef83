// Checkers of triangulate()'s stages (triangulation_checks.hpp).
#include "triangulation_checks.hpp"

#include <string>

#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/checked.hpp"
#include "sweep_order.hpp"

namespace edgeland::detail {
namespace {

// How often the face's boundary, walked once around, switches between going down and going up
// in the sweep order: 2 for a monotone face.
std::size_t direction_changes(const Polygon& p, std::span<const std::uint32_t> face) {
  const std::size_t m = face.size();
  std::size_t changes = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const Point64 a = p[face[k]], b = p[face[(k + 1) % m]], c = p[face[(k + 2) % m]];
    if (sweeps_before(a, b) != sweeps_before(b, c)) ++changes;
  }
  return changes;
}

}  // namespace

void check_monotone_faces(const Polygon& polygon, std::size_t diagonal_count, const Faces& faces) {
  if (faces.count() != diagonal_count + 1)
    fail_stage("triangulate", std::to_string(diagonal_count) + " diagonals gave " +
                                  std::to_string(faces.count()) + " faces");
  if (faces.vertices.size() != polygon.size() + 2 * diagonal_count)
    fail_stage("triangulate", "the faces do not use each side once");
  for (std::size_t f = 0; f < faces.count(); ++f) {
    if (faces.face(f).size() < 3 || direction_changes(polygon, faces.face(f)) != 2)
      fail_stage("triangulate", "face " + std::to_string(f) + " is not monotone");
  }
}

void check_triangles(const Polygon& polygon, const std::vector<Triangle>& triangles) {
  if (triangles.size() + 2 != polygon.size())
    fail_stage("triangulate", std::to_string(triangles.size()) + " triangles for " +
                                  std::to_string(polygon.size()) + " vertices");
  arith::Checked<Int128> sum = 0;
  for (const Triangle& t : triangles) {
    if (t.a >= polygon.size() || t.b >= polygon.size() || t.c >= polygon.size())
      fail_stage("triangulate", "a triangle index is out of range");
    const Int128 twice = orient_det(polygon[t.a], polygon[t.b], polygon[t.c]);
    if (twice <= 0) fail_stage("triangulate", "a triangle is not counter-clockwise");
    sum = sum + arith::Checked<Int128>(twice);
  }
  if (sum.v != twice_signed_area(polygon))
    fail_stage("triangulate", "the triangles' areas do not sum to the polygon's");
}

}  // namespace edgeland::detail
