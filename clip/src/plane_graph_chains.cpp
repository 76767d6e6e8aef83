// build_plane_graph, step 1: which segments are chained (plane_graph_build.hpp).
//
// Chains of untouched segments (their points are read from the segment list: an untouched
// segment is never listed) are found in one pass per ring. A chain starts after a touched
// segment; in a ring nothing touches, at its smallest vertex and halfway round (no edge may be a
// loop). A chain's smallest point must be one of its ends, so that every connected component's
// smallest point is a graph vertex (labeling starts each component there, west of it). Ring
// minima would not do: the ring's smallest vertex may belong only to pieces that cancel (a spike
// folded back onto itself), leaving a chain's interior point the smallest. So a chain whose
// least point is interior and below its end is cut there.
#include <algorithm>

#include "plane_graph_build.hpp"

namespace edgeland::detail::plane_graph_build {
namespace {

// The ring occupying segments [begin, begin + size) (rings are consecutive; next wraps round).
struct RingSpan {
  std::uint32_t begin, size;
};

RingSpan ring_at(const std::vector<std::uint32_t>& next, std::uint32_t begin) {
  std::uint32_t last = begin;
  while (next[last] == last + 1) ++last;  // next[last] == begin
  return {begin, last - begin + 1};
}

// The chain of `segments` segments of `ring` from ring position `pos` (modulo its size).
void add_chain(const RingSpan& ring, std::uint32_t pos, std::uint32_t segments, ChainPlan& plan) {
  PlaneGraph::Chain c;
  c.first = ring.begin + pos % ring.size;
  c.count = segments - 1;
  c.ring_begin = ring.begin;
  c.ring_len = ring.size;
  plan.chains.push_back(c);
}

// A ring nothing touches: two chains, from its smallest vertex and from halfway round.
void chain_whole_ring(const std::vector<Segment>& segments, const RingSpan& ring, ChainPlan& plan) {
  std::uint32_t smallest = 0;
  for (std::uint32_t k = 1; k < ring.size; ++k)
    if (segments[ring.begin + k].a < segments[ring.begin + smallest].a) smallest = k;
  add_chain(ring, smallest, ring.size / 2, plan);
  add_chain(ring, smallest + ring.size / 2, ring.size - ring.size / 2, plan);
}

// The untouched segments between two touched ones, in chain order: [after, upto) and then, when
// the gap wraps past the ring's end, [ring.begin, ring.begin + wrapped).
struct Gap {
  std::uint32_t after, upto, wrapped;
  std::uint32_t size() const { return (upto - after) + wrapped; }
  std::uint32_t segment(const RingSpan& ring, std::uint32_t k) const {
    return k < upto - after ? after + k : ring.begin + (k - (upto - after));
  }
};

// The gap's offset of its least start point (the first, on ties). Two plain loops, not one
// through Gap::segment: this scans every untouched segment, nearly all of a smooth input.
std::uint32_t least_start(const std::vector<Segment>& segments, const RingSpan& ring,
                          const Gap& gap) {
  std::uint32_t least = 0;
  Point64 least_point = segments[gap.segment(ring, 0)].a;
  for (std::uint32_t t = gap.after; t < gap.upto; ++t)
    if (segments[t].a < least_point) {
      least_point = segments[t].a;
      least = t - gap.after;
    }
  for (std::uint32_t t = ring.begin; t < ring.begin + gap.wrapped; ++t)
    if (segments[t].a < least_point) {
      least_point = segments[t].a;
      least = (gap.upto - gap.after) + (t - ring.begin);
    }
  return least;
}

// One gap as a chain, or as two when its least point is interior and below its end.
void chain_gap(const std::vector<Segment>& segments, const RingSpan& ring, const Gap& gap,
               ChainPlan& plan) {
  const std::uint32_t least = least_start(segments, ring, gap);
  const std::uint32_t from = gap.after - ring.begin;  // ring position of the first segment
  const Point64 chain_end = segments[gap.segment(ring, gap.size() - 1)].b;
  if (least != 0 && segments[gap.segment(ring, least)].a < chain_end) {
    add_chain(ring, from, least, plan);
    add_chain(ring, from + least, gap.size() - least, plan);
  } else {
    add_chain(ring, from, gap.size(), plan);
  }
}

// A ring with touched segments (plan.touched[first_touched ..]): every gap between consecutive
// touched segments, cyclically, is a chain.
void chain_gaps(const std::vector<Segment>& segments, const RingSpan& ring,
                std::size_t first_touched, ChainPlan& plan) {
  const auto& ids = plan.touched;
  for (std::size_t i = first_touched; i < ids.size(); ++i) {
    const bool wraps = i + 1 == ids.size();
    const Gap gap{ids[i] + 1, wraps ? ring.begin + ring.size : ids[i + 1],
                  wraps ? ids[first_touched] - ring.begin : 0};
    if (gap.size() > 0) chain_gap(segments, ring, gap, plan);
  }
}

}  // namespace

void plan_chains(const EdgeList& edges, const std::vector<std::uint8_t>& touched, ChainPlan& plan) {
  const auto n = static_cast<std::uint32_t>(edges.next.size());
  plan.chains.clear();
  plan.touched.clear();
  plan.touched.reserve(n);
  for (std::uint32_t b = 0; b < n;) {
    const RingSpan ring = ring_at(edges.next, b);
    const std::size_t first_touched = plan.touched.size();
    for (std::uint32_t s = b; s < b + ring.size; ++s)
      if (touched[s]) plan.touched.push_back(s);
    if (plan.touched.size() == first_touched) {
      chain_whole_ring(edges.segments, ring, plan);
    } else {
      chain_gaps(edges.segments, ring, first_touched, plan);
    }
    b += ring.size;
  }
  // Chains in the order of their first segment (as every graph edge list is built in segment
  // order: deterministic and independent of where the walks began).
  std::sort(
      plan.chains.begin(), plan.chains.end(),
      [](const PlaneGraph::Chain& x, const PlaneGraph::Chain& y) { return x.first < y.first; });
}

}  // namespace edgeland::detail::plane_graph_build
