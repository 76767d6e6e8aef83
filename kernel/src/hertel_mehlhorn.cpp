// Stage 2 of convex_pieces(): Hertel-Mehlhorn merging (hertel_mehlhorn.hpp).
//
// Two convex pieces P and Q sharing the diagonal a -> b (P on its left) merge into a polygon
// whose angles differ from theirs only at a and b, where each is the sum of P's and Q's angles
// (each in (0, 180]). The sum lies in (0, 360), so the sign of one orientation test says whether
// it is below, at or above 180 degrees; the merged piece is convex exactly when neither is above.
#include "hertel_mehlhorn.hpp"

#include <vector>

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

// Whether the diagonal from polygon vertex v to point u alone splits v's angle into two parts of
// at most 180 degrees: true at a convex or straight vertex, and at a reflex one when u lies in
// the sector where the reversed edges overlap.
bool splits_angle(const Polygon& polygon, std::uint32_t v, Point64 u) {
  const std::size_t n = polygon.size();
  const Point64 at = polygon[v], next = polygon[(v + 1) % n], prev = polygon[(v + n - 1) % n];
  return orientation(at, next, u) != Orientation::kClockwise &&
         orientation(at, u, prev) != Orientation::kClockwise;
}

// How many of the diagonal's two ends it splits alone (0, 1 or 2).
int splitting_ends(const PieceMesh& mesh, std::uint32_t h) {
  const std::uint32_t t = mesh.twin(h);
  return splits_angle(mesh.polygon(), mesh.origin(h), mesh.point(t)) +
         splits_angle(mesh.polygon(), mesh.origin(t), mesh.point(h));
}

// Each diagonal once, in three rounds: first those that split neither end's angle alone (at a
// reflex vertex some other diagonal must stay), last those that split both (a reflex vertex
// needs only one of them). So at a reflex vertex the diagonals that cannot resolve it go first,
// and one that can is the likeliest to be the one kept.
std::vector<std::uint32_t> merge_order(const PieceMesh& mesh) {
  std::vector<std::uint32_t> rounds[3];
  const auto count = static_cast<std::uint32_t>(mesh.half_edge_count());
  for (std::uint32_t h = 0; h < count; ++h) {
    const std::uint32_t t = mesh.twin(h);
    if (t != kNoTwin && h < t) rounds[splitting_ends(mesh, h)].push_back(h);
  }
  std::vector<std::uint32_t> order = std::move(rounds[0]);
  order.insert(order.end(), rounds[1].begin(), rounds[1].end());
  order.insert(order.end(), rounds[2].begin(), rounds[2].end());
  return order;
}

}  // namespace

void merge_convex_pieces(PieceMesh& mesh, std::size_t max_corners) {
  for (const std::uint32_t h : merge_order(mesh)) {
    const Merged m = merged_across(mesh, h);
    if (m.convex && m.corners <= max_corners) mesh.merge_across(h, m.corners);
  }
}

}  // namespace edgeland::detail
