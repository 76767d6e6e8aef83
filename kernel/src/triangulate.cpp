// triangulate(): monotone pieces (stage 1: diagonals, stage 2: faces), then each piece
// triangulated (stage 3). kernel/README.md states what each stage hands the next.
#include "edgeland/kernel/triangulate.hpp"

#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/triangulation.hpp"
#include "edgeland/kernel/validate.hpp"
#include "monotone_partition.hpp"
#include "monotone_triangulation.hpp"
#include "polygon_faces.hpp"
#include "triangulation_checks.hpp"

namespace edgeland {
namespace detail {

void require_valid_polygon(const Polygon& polygon) {
  if (polygon.size() > kMaxPolygonAlgorithmVertices)
    throw TooManyVertices(kMaxPolygonAlgorithmVertices, polygon.size());
  const ValidationReport report = validate(polygon, 1);
  if (!report.ok()) throw_invalid_input(Operand::kPolygon, report.violations.front());
}

std::vector<Triangle> triangulate_valid(const Polygon& polygon) {
  const std::vector<Diagonal> diagonals = monotone_diagonals(polygon);
  const Faces faces = faces_cut_by(polygon, diagonals);
  if constexpr (EDGELAND_ASSERTS_ENABLED) check_monotone_faces(polygon, diagonals.size(), faces);
  std::vector<Triangle> triangles;
  triangles.reserve(polygon.size() - 2);
  for (std::size_t f = 0; f < faces.count(); ++f)
    triangulate_monotone(polygon, faces.face(f), triangles);
  if constexpr (EDGELAND_ASSERTS_ENABLED) check_triangles(polygon, triangles);
  return triangles;
}

}  // namespace detail

std::vector<Triangle> triangulate(const Polygon& polygon) {
  detail::require_valid_polygon(polygon);
  return detail::triangulate_valid(polygon);
}

}  // namespace edgeland
