// Strict simplicity of one ring by the sweep of validate_report_sweep.hpp: non-adjacent edges share
// no point. Adjacent edges share their common vertex; if they share more they fold back, which
// check_spikes reports, so pairs of adjacent edges are never reported here.
#include <array>

#include "edgeland/kernel/predicates.hpp"
#include "validate_checks.hpp"

namespace edgeland::detail {
namespace {

class RingSimplicityCheck {
 public:
  RingSimplicityCheck(const std::vector<SweepEdge>& edges, std::size_t ring_size)
      : edges_(edges), n_(ring_size) {}

  // Every edge at q contains q: any two of them that are not neighbours in the ring touch.
  std::optional<Violation> at_event(const EventView& view) {
    // In a ring of n >= 4 edges an edge has two neighbours, so among any 4 edges at one point
    // the first has a non-neighbour; with n == 3 every pair is adjacent.
    std::array<std::size_t, 4> at{};
    std::size_t k = 0;
    for (const auto* list : {&view.ending, &view.through, &view.starting}) {
      for (const std::size_t e : *list) {
        if (k == at.size()) break;
        at[k++] = e;
      }
    }
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t j = i + 1; j < k; ++j) {
        if (!adjacent_in_ring(at[i], at[j])) return report(at[i], at[j], view.q);
      }
    }
    return std::nullopt;
  }

  std::optional<Violation> after_event(Point64, const std::vector<std::size_t>&) {
    return std::nullopt;
  }

  std::optional<Violation> adjacent(std::size_t a, std::size_t b) {
    if (adjacent_in_ring(a, b)) return std::nullopt;
    const Segment sa{edges_[a].left, edges_[a].right};
    const Segment sb{edges_[b].left, edges_[b].right};
    const SegmentIntersection hit = intersect(sa, sb);
    switch (hit.relation) {
      case SegmentRelation::kDisjoint:
        return std::nullopt;
      case SegmentRelation::kOverlapping:
        // Not reached by tests: an overlap starts at the later left end, an event where both
        // edges contain q, so at_event() has reported the pair before they become neighbours.
        return report(a, b, hit.overlap_from);
      case SegmentRelation::kCrossing:
      case SegmentRelation::kTouching:
        return report(a, b, round_to_grid(hit.point));
    }
    return std::nullopt;  // Not reached by tests: the switch covers every SegmentRelation.
  }

 private:
  bool adjacent_in_ring(std::size_t a, std::size_t b) const noexcept {
    const std::size_t i = edges_[a].edge, j = edges_[b].edge;
    return (i + 1) % n_ == j || (j + 1) % n_ == i;
  }

  std::optional<Violation> report(std::size_t a, std::size_t b, Point64 where) const {
    Violation v;
    v.rule = Rule::kSelfIntersection;
    v.polygon = edges_[a].polygon;
    v.edge = std::min(edges_[a].edge, edges_[b].edge);
    v.other_edge = std::max(edges_[a].edge, edges_[b].edge);
    v.where = where;
    return v;
  }

  const std::vector<SweepEdge>& edges_;
  std::size_t n_;
};

}  // namespace

std::optional<Violation> find_self_intersection(const std::vector<SweepEdge>& edges,
                                                std::size_t ring_size) {
  if (ring_size <= 3) return std::nullopt;  // every pair of edges is adjacent
  RingSimplicityCheck check(edges, ring_size);
  return run_sweep(edges, check);
}

}  // namespace edgeland::detail
