// convex_pieces(): triangulate (stage 1), merge into convex pieces (stage 2), write each piece
// without its straight vertices (stage 3). kernel/README.md states what each stage hands on.
#include "edgeland/kernel/convex_pieces.hpp"

#include "convex_pieces_checks.hpp"
#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "edgeland/kernel/triangulation.hpp"
#include "hertel_mehlhorn.hpp"
#include "piece_mesh.hpp"

namespace edgeland {
namespace {

// The piece holding half-edge `first`, its corners only, counter-clockwise; marks its
// half-edges taken.
// Whether the piece turns strictly at the origin of half-edge h.
bool corner_at(const detail::PieceMesh& mesh, std::uint32_t h) {
  return orientation(mesh.point(mesh.prev(h)), mesh.point(h), mesh.point(mesh.next(h))) ==
         Orientation::kCounterClockwise;
}

Polygon corners_of_piece(const detail::PieceMesh& mesh, std::uint32_t first,
                         std::vector<char>& taken) {
  std::size_t count = 0;  // counted first: the piece is allocated once, at its size
  std::uint32_t h = first;
  do {
    count += corner_at(mesh, h) ? 1 : 0;
    h = mesh.next(h);
  } while (h != first);
  Polygon piece;
  piece.reserve(count);
  do {
    taken[h] = 1;
    if (corner_at(mesh, h)) piece.push_back(mesh.point(h));
    h = mesh.next(h);
  } while (h != first);
  return piece;
}

// The polygon without its straight vertices: the same region, still valid (strictly simple,
// counter-clockwise, at least 3 corners as its area is positive). Pieces never have straight
// vertices, and a triangulation through them would only add diagonals to merge away.
Polygon corners_of(const Polygon& polygon) {
  Polygon corners;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 before = polygon[(i + n - 1) % n], after = polygon[(i + 1) % n];
    if (orientation(before, polygon[i], after) != Orientation::kCollinear)
      corners.push_back(polygon[i]);
  }
  return corners;
}

std::vector<Polygon> pieces_of(const detail::PieceMesh& mesh) {
  std::vector<Polygon> pieces;
  detail::ScratchVector<char> taken;
  taken.assign(mesh.half_edge_count(), 0);
  for (std::uint32_t h = 0; h < mesh.half_edge_count(); ++h)
    if (mesh.alive(h) && !taken[h]) pieces.push_back(corners_of_piece(mesh, h, taken));
  return pieces;
}

// Stages 2 and 3 over the triangles of the polygon's corners.
std::vector<Polygon> pieces_from(const Polygon& polygon, const Polygon& corners,
                                 const std::vector<Triangle>& triangles, std::size_t max_vertices) {
  detail::PieceMesh mesh(corners, triangles);
  detail::merge_convex_pieces(mesh, max_vertices);
  std::vector<Polygon> pieces = pieces_of(mesh);
  if constexpr (EDGELAND_ASSERTS_ENABLED)
    detail::check_convex_pieces(polygon, pieces, max_vertices);
  return pieces;
}

void require_piece_size(std::size_t max_vertices) {
  if (max_vertices < 3) throw InvalidArgument("max_vertices", max_vertices, 3);
}

}  // namespace

std::vector<Polygon> convex_pieces(const Polygon& polygon, std::size_t max_vertices) {
  require_piece_size(max_vertices);
  detail::require_valid_polygon(polygon);
  const Polygon corners = corners_of(polygon);
  return pieces_from(polygon, corners, detail::triangulate_valid(corners), max_vertices);
}

// triangulate() keeps straight vertices and stage 1 drops them, so the triangles are shared only
// when there are none.
TrianglesAndPieces triangles_and_convex_pieces(const Polygon& polygon, std::size_t max_vertices) {
  require_piece_size(max_vertices);
  detail::require_valid_polygon(polygon);
  return detail::triangles_and_convex_pieces_valid(polygon, max_vertices);
}

namespace detail {

TrianglesAndPieces triangles_and_convex_pieces_valid(const Polygon& polygon,
                                                     std::size_t max_vertices) {
  require_piece_size(max_vertices);
  if constexpr (EDGELAND_ASSERTS_ENABLED) require_valid_polygon(polygon);
  TrianglesAndPieces out;
  out.triangles = triangulate_valid(polygon);
  const Polygon corners = corners_of(polygon);
  out.pieces = corners.size() == polygon.size()
                   ? pieces_from(polygon, corners, out.triangles, max_vertices)
                   : pieces_from(polygon, corners, triangulate_valid(corners), max_vertices);
  return out;
}

}  // namespace detail
}  // namespace edgeland
