#include "validate_sweep.hpp"

#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/formulas.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland::detail {

void append_ring_edges(const Ring& ring, std::size_t polygon, std::vector<SweepEdge>& out) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 a = ring[i];
    const Point64 b = ring[(i + 1) % n];
    const bool forward = a < b;
    out.push_back(SweepEdge{forward ? a : b, forward ? b : a, polygon, i, forward});
  }
}

int side_of_point(const SweepEdge& t, Point64 q) noexcept {
  if (is_vertical(t)) return 0;
  // t runs rightward, so q left of t means q above it, i.e. t below q.
  return -sign_of(orient_det(t.left, t.right, q));
}

int compare_directions(const SweepEdge& a, const SweepEdge& b) noexcept {
  const bool av = is_vertical(a), bv = is_vertical(b);
  if (av || bv) return av == bv ? 0 : (av ? 1 : -1);
  // Both point rightward: b turning counter-clockwise from a means b leaves above a.
  // Differences of in-range coordinates fit 33 bits and the cross product 66 bits (proofs/).
  using W = arith::Checked<Int128>;
  const W c = formulas::cross<W>(W(a.right.x) - W(a.left.x), W(a.right.y) - W(a.left.y),
                                 W(b.right.x) - W(b.left.x), W(b.right.y) - W(b.left.y));
  return -sign_of(c.v);
}

int StatusOrder::compare_at_event(const SweepEdge& a, const SweepEdge& b) const noexcept {
  const Point64 q = *event_;
  const bool a_new = a.left == q, b_new = b.left == q;
  if (a_new && b_new) return compare_directions(a, b);
  if (a_new) {
    const int s = side_of_point(b, q);
    return s != 0 ? -s : compare_directions(a, b);
  }
  // b is the new edge (the status never compares two old ones).
  const int s = side_of_point(a, q);
  return s != 0 ? s : compare_directions(a, b);
}

}  // namespace edgeland::detail
