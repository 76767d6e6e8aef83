#include "validate_sweep.hpp"

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

void sort_for_sweep(std::vector<SweepEdge>& edges) {
  std::sort(edges.begin(), edges.end(), [](const SweepEdge& a, const SweepEdge& b) {
    return a.left < b.left || (a.left == b.left && (a.polygon < b.polygon ||
                                                    (a.polygon == b.polygon && a.edge < b.edge)));
  });
}

}  // namespace edgeland::detail
