// Stage 2 of convex_pieces(): Hertel-Mehlhorn merging (hertel_mehlhorn.hpp).
//
// Two convex pieces P and Q sharing the diagonal a -> b (P on its left) merge into a polygon
// whose angles differ from theirs only at a and b, where each is the sum of P's and Q's angles
// (each in (0, 180]). The sum lies in (0, 360), so the sign of one orientation test says whether
// it is below, at or above 180 degrees; the merged piece is convex exactly when neither is above.
#include "hertel_mehlhorn.hpp"

#include "edgeland/kernel/predicates.hpp"

namespace edgeland::detail {
namespace {

int strict_turn(Point64 a, Point64 b, Point64 c) {
  return orientation(a, b, c) == Orientation::kCounterClockwise ? 1 : 0;
}

struct Merged {
  bool convex = false;
  std::uint32_t corners = 0;
};

// The merged piece across diagonal h: convex or not, and its corner count (the two pieces'
// corners, less their corners at a and b, plus the merged piece's corners there).
Merged merged_across(PieceMesh& mesh, std::uint32_t h) {
  const std::uint32_t t = mesh.twin(h);
  const Point64 a = mesh.point(h), b = mesh.point(t);
  const Point64 p_before_a = mesh.point(mesh.prev(h)),
                p_after_b = mesh.point(mesh.next(mesh.next(h)));
  const Point64 q_before_b = mesh.point(mesh.prev(t)),
                q_after_a = mesh.point(mesh.next(mesh.next(t)));
  if (orientation(p_before_a, a, q_after_a) == Orientation::kClockwise ||
      orientation(q_before_b, b, p_after_b) == Orientation::kClockwise)
    return {};
  const int before = strict_turn(p_before_a, a, b) + strict_turn(b, a, q_after_a) +
                     strict_turn(a, b, p_after_b) + strict_turn(q_before_b, b, a);
  const int after = strict_turn(p_before_a, a, q_after_a) + strict_turn(q_before_b, b, p_after_b);
  const auto corners = static_cast<std::uint32_t>(
      static_cast<int>(mesh.corners(h) + mesh.corners(t)) - before + after);
  return {true, corners};
}

}  // namespace

void merge_convex_pieces(PieceMesh& mesh, std::size_t max_corners) {
  const auto count = static_cast<std::uint32_t>(mesh.half_edge_count());
  for (std::uint32_t h = 0; h < count; ++h) {
    const std::uint32_t t = mesh.twin(h);
    if (t == kNoTwin || t < h || !mesh.alive(h)) continue;  // each diagonal once
    const Merged m = merged_across(mesh, h);
    if (m.convex && m.corners <= max_corners) mesh.merge_across(h, m.corners);
  }
}

}  // namespace edgeland::detail
