// Stage 2 of triangulate(): tracing the faces of a polygon and its diagonals (a doubly-connected
// edge list in compressed rows: the sides leaving each vertex, sorted by angle).
#include "polygon_faces.hpp"

#include <algorithm>

#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/scratch.hpp"

namespace edgeland::detail {
namespace {

constexpr std::uint32_t kPolygonEdge = 0xFFFFFFFFu;

// A side leaving a vertex: to `to`, along diagonal `diagonal` (or a polygon edge).
struct Side {
  std::uint32_t to = 0;
  std::uint32_t diagonal = kPolygonEdge;
};

// The sides leaving each vertex v, counter-clockwise from v's outgoing polygon edge: first the
// edge to v + 1, then the diagonals, then the edge to v - 1. Rows are offsets into `sides`.
struct SideRows {
  ScratchVector<Side> sides;
  ScratchVector<std::uint32_t> first;  // per vertex, and one past the end
};

// Whether w1 comes before w2 counter-clockwise around v, starting at direction v -> next. Both
// lie strictly inside the polygon's angle at v (below a full turn), and no two in one direction.
bool ccw_before(Point64 v, Point64 next, Point64 w1, Point64 w2) {
  const bool first_half1 = orientation(v, next, w1) == Orientation::kCounterClockwise;
  const bool first_half2 = orientation(v, next, w2) == Orientation::kCounterClockwise;
  if (first_half1 != first_half2) return first_half1;
  return orientation(v, w1, w2) == Orientation::kCounterClockwise;
}

SideRows side_rows(const Polygon& p, const std::vector<Diagonal>& diagonals) {
  const auto n = static_cast<std::uint32_t>(p.size());
  SideRows rows;
  rows.first.assign(n + 1, 0);
  for (const Diagonal& d : diagonals) {
    ++rows.first[d.from + 1];
    ++rows.first[d.to + 1];
  }
  for (std::uint32_t v = 0; v < n; ++v) rows.first[v + 1] += rows.first[v] + 2;
  rows.sides.resize(rows.first[n]);
  ScratchVector<std::uint32_t> fill;
  fill.assign(rows.first.begin(), rows.first.end() - 1);
  for (std::uint32_t v = 0; v < n; ++v) rows.sides[fill[v]++] = {v + 1 == n ? 0 : v + 1};
  for (std::uint32_t d = 0; d < diagonals.size(); ++d) {
    rows.sides[fill[diagonals[d].from]++] = {diagonals[d].to, d};
    rows.sides[fill[diagonals[d].to]++] = {diagonals[d].from, d};
  }
  for (std::uint32_t v = 0; v < n; ++v) {
    rows.sides[fill[v]] = {v == 0 ? n - 1 : v - 1};
    const Point64 at = p[v], next = p[v + 1 == n ? 0 : v + 1];
    std::sort(rows.sides.begin() + rows.first[v] + 1, rows.sides.begin() + fill[v],
              [&](const Side& a, const Side& b) { return ccw_before(at, next, p[a.to], p[b.to]); });
  }
  return rows;
}

// For each side u -> v, the index of its reverse v -> u.
ScratchVector<std::uint32_t> reverse_sides(const SideRows& rows, std::size_t diagonal_count) {
  const auto n = static_cast<std::uint32_t>(rows.first.size() - 1);
  ScratchVector<std::uint32_t> reverse, diagonal_side;
  reverse.resize(rows.sides.size());
  diagonal_side.assign(2 * diagonal_count, kPolygonEdge);
  for (std::uint32_t v = 0; v < n; ++v) {
    const std::uint32_t out = rows.first[v], last = rows.first[v + 1] - 1;
    const std::uint32_t next = v + 1 == n ? 0 : v + 1;
    reverse[out] = rows.first[next + 1] - 1;  // v -> v+1 against v+1 -> v, last of its row
    reverse[rows.first[next + 1] - 1] = out;
    for (std::uint32_t s = out + 1; s < last; ++s) {
      const std::uint32_t d = rows.sides[s].diagonal;
      const std::uint32_t slot = diagonal_side[2 * d] == kPolygonEdge ? 2 * d : 2 * d + 1;
      diagonal_side[slot] = s;
    }
  }
  for (std::size_t d = 0; d < diagonal_count; ++d) {
    reverse[diagonal_side[2 * d]] = diagonal_side[2 * d + 1];
    reverse[diagonal_side[2 * d + 1]] = diagonal_side[2 * d];
  }
  return reverse;
}

}  // namespace

Faces faces_cut_by(const Polygon& polygon, const std::vector<Diagonal>& diagonals) {
  const SideRows rows = side_rows(polygon, diagonals);
  const ScratchVector<std::uint32_t> reverse = reverse_sides(rows, diagonals.size());
  const auto n = static_cast<std::uint32_t>(polygon.size());
  // Sides with the interior on their left: all but each row's last (v -> v - 1, outside left).
  ScratchVector<char> done;
  done.assign(rows.sides.size(), 0);
  for (std::uint32_t v = 0; v < n; ++v) done[rows.first[v + 1] - 1] = 1;
  Faces faces;
  faces.vertices.reserve(n + 2 * diagonals.size());
  for (std::uint32_t v = 0; v < n; ++v) {
    for (std::uint32_t s = rows.first[v]; s + 1 < rows.first[v + 1]; ++s) {
      if (done[s]) continue;
      // Walk the face: from side u -> w, the next side leaves w just clockwise of w -> u.
      std::uint32_t from = v;
      for (std::uint32_t side = s; !done[side]; side = reverse[side] - 1) {
        done[side] = 1;
        faces.vertices.push_back(from);
        from = rows.sides[side].to;
      }
      faces.offsets.push_back(static_cast<std::uint32_t>(faces.vertices.size()));
    }
  }
  return faces;
}

}  // namespace edgeland::detail
