// Disjoint interiors of a set of strictly simple counter-clockwise rings, by the sweep of
// validate_report_sweep.hpp.
//
// Each ring has winding number 1 inside and 0 outside, so the winding number of all rings
// together counts the members covering a point: interiors are pairwise disjoint iff it never
// reaches 2. Two members that cross are found as crossing status neighbours. Without
// crossings, every face of the arrangement of all edges has a leftmost point that is an
// event point q, where the face is one of the sectors between the edges leaving q to the
// right. Walking those sectors counter-clockwise from straight down, the winding number
// changes by +1 across an edge leaving q along its ring direction (its interior, on its left,
// is the counter-clockwise side) and by -1 across one arriving at q. The start value, just
// below q, is the winding number above the status edge below q, stored when that edge was
// placed; it stays valid along the edge because nothing crosses it and whatever touches it
// passes an event point, where it is refreshed. Edges in one direction through q (a shared
// edge seen from both sides) are crossed together: the sector between them is empty.
//
// Beside the count the walk keeps which member covers a sector, so a sector covered twice
// names both members: the one entering there and the one already covering it.
#include "edgeland/kernel/predicates.hpp"
#include "validate_checks.hpp"

namespace edgeland::detail {
namespace {

class DisjointInteriorsCheck {
 public:
  explicit DisjointInteriorsCheck(const std::vector<SweepEdge>& edges)
      : edges_(edges), cover_(edges.size(), 0), owner_(edges.size(), kNone) {}

  std::optional<Violation> at_event(const EventView& view) {
    // Edges through q with q inside both either overlap collinearly or cross at q.
    for (std::size_t i = 1; i < view.through.size(); ++i) {
      const std::size_t a = view.through[i - 1], b = view.through[i];
      if (compare_directions(edges_[a], edges_[b]) != 0) return report(a, b, view.q);
    }
    start_cover_ = view.below == kNone ? 0 : cover_[view.below];
    start_owner_ = view.below == kNone ? kNone : owner_[view.below];
    return std::nullopt;
  }

  // `block` holds the edges through or leaving q bottom-up, i.e. in counter-clockwise order
  // of their rays to the right of q, the vertical one last.
  std::optional<Violation> after_event(Point64 q, const std::vector<std::size_t>& block) {
    int cover = start_cover_;
    std::size_t owner = start_owner_;  // edge whose member covers the current sector
    for (std::size_t first = 0; first < block.size();) {
      std::size_t last = first + 1;
      while (last < block.size() &&
             compare_directions(edges_[block[first]], edges_[block[last]]) == 0) {
        ++last;
      }
      std::size_t entering = kNone;
      for (std::size_t i = first; i < last; ++i) {
        const std::size_t e = block[i];
        if (edges_[e].forward) {
          if (entering != kNone) return report(entering, e, q);  // same edge, same direction
          entering = e;
          ++cover;
        } else {
          --cover;
        }
      }
      if (cover >= 2) return report(entering, owner, q);
      owner = cover == 1 && entering != kNone ? entering : (cover == 0 ? kNone : owner);
      for (std::size_t i = first; i < last; ++i) {
        cover_[block[i]] = cover;
        owner_[block[i]] = owner;
      }
      first = last;
    }
    return std::nullopt;
  }

  std::optional<Violation> adjacent(std::size_t a, std::size_t b) {
    if (edges_[a].polygon == edges_[b].polygon) return std::nullopt;
    const SegmentIntersection hit = intersect(Segment{edges_[a].left, edges_[a].right},
                                              Segment{edges_[b].left, edges_[b].right});
    if (hit.relation != SegmentRelation::kCrossing) return std::nullopt;
    return report(a, b, round_to_grid(hit.point));
  }

 private:
  // Both edges' members cover points near `where`. Lower polygon index first.
  std::optional<Violation> report(std::size_t a, std::size_t b, Point64 where) const {
    Violation v;
    v.rule = Rule::kOverlappingInteriors;
    v.where = where;
    if (b == kNone) {  // unreachable while the walk's counts are exact; keep the report
      v.polygon = edges_[a].polygon;
      v.edge = edges_[a].edge;
      return v;
    }
    const SweepEdge& ea = edges_[a].polygon <= edges_[b].polygon ? edges_[a] : edges_[b];
    const SweepEdge& eb = &ea == &edges_[a] ? edges_[b] : edges_[a];
    v.polygon = ea.polygon;
    v.edge = ea.edge;
    v.other_polygon = eb.polygon;
    v.other_edge = eb.edge;
    return v;
  }

  const std::vector<SweepEdge>& edges_;
  std::vector<int> cover_;          // winding number just above each placed edge
  std::vector<std::size_t> owner_;  // an edge of the member covering that face, if one does
  int start_cover_ = 0;
  std::size_t start_owner_ = kNone;
};

}  // namespace

std::optional<Violation> find_overlap(const std::vector<SweepEdge>& edges) {
  DisjointInteriorsCheck check(edges);
  return run_sweep(edges, check);
}

}  // namespace edgeland::detail
