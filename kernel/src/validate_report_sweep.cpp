// The reporting checks' sweep (validate_report_sweep.hpp): ring edges in sweep order.
#include "validate_report_sweep.hpp"

#include <algorithm>
#include <cstdint>

#include "validate_event_sort.hpp"

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
  const auto by_origin = [](const SweepEdge& a, const SweepEdge& b) {
    return a.polygon < b.polygon || (a.polygon == b.polygon && a.edge < b.edge);
  };
  if (edges.size() >= UINT32_MAX || !std::is_sorted(edges.begin(), edges.end(), by_origin)) {
    // Not reached by tests: validate() appends rings in polygon order, each edge by edge, and
    // no test has 2^32 edges; kept so any caller's order and size work.
    std::sort(edges.begin(), edges.end(), [&](const SweepEdge& a, const SweepEdge& b) {
      return a.left < b.left || (a.left == b.left && by_origin(a, b));
    });
    return;
  }
  // Listed by (polygon, edge), as append_ring_edges makes them: a stable sort by left end
  // gives the same order, from 64-bit keys (validate_event_sort.hpp).
  const std::vector<KeyedVertex> order =
      sorted_by_point(edges.size(), [&](std::size_t i) { return edges[i].left; });
  std::vector<SweepEdge> sorted;
  sorted.reserve(edges.size());
  for (const KeyedVertex& k : order) sorted.push_back(edges[k.vertex]);
  edges.swap(sorted);
}

}  // namespace edgeland::detail
