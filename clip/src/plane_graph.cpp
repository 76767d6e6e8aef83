// The plane graph: its build, step by step (plane_graph_build.hpp), and the reading of its chains.
#include "plane_graph.hpp"

#include <algorithm>

#include "plane_graph_build.hpp"

namespace edgeland::detail {

void PlaneGraph::append_points(std::uint32_t h, std::vector<Point64>& out) const {
  const std::uint32_t e = h >> 1, m = interior_count(e);
  out.push_back(vertices[origin(h)]);
  if (m == 0) return;
  // Walk the chain's segments in ring order, forwards or backwards as h requires.
  const Chain& c = chain[e];
  const bool forward_in_ring = ((h & 1) != 0) == c.reversed;
  // The interior points are the starts of the chain's segments 1 .. m, which lie in at most two
  // contiguous stretches of the ring (it may wrap once): copied as such, no index arithmetic
  // per point. Capacity grows geometrically: an exact-size resize per chain made glibc hand the
  // large output rings back and forth to the system (page faults, a third slower at 10^4).
  const std::vector<Segment>& segs = *segments;
  const std::uint32_t at = c.first - c.ring_begin + 1;  // ring position of segment 1
  const std::uint32_t first_part = std::min(m, c.ring_len - std::min(at, c.ring_len));
  const std::uint32_t p0 = c.ring_begin + (at < c.ring_len ? at : at - c.ring_len);
  if (out.capacity() < out.size() + m) out.reserve(std::max(out.size() + m, 2 * out.capacity()));
  if (forward_in_ring) {
    for (std::uint32_t i = 0; i < first_part; ++i) out.push_back(segs[p0 + i].a);
    for (std::uint32_t i = first_part; i < m; ++i)
      out.push_back(segs[c.ring_begin + (i - first_part)].a);
  } else {
    for (std::uint32_t i = m; i-- > first_part;)
      out.push_back(segs[c.ring_begin + (i - first_part)].a);
    for (std::uint32_t i = first_part; i-- > 0;) out.push_back(segs[p0 + i].a);
  }
}

namespace {

// Steps 1-3 (plane_graph_build.hpp). Their arrays die here, before the angular sort: at combs
// of 10^5 vertices that sort was the peak of the whole clip, with them alive beside it.
void build_edges(const EdgeList& edges, const std::vector<Fragment>& fragments,
                 const std::vector<std::uint8_t>& touched, PlaneGraph& g) {
  using namespace plane_graph_build;
  const FragmentRanges ranges(fragments, static_cast<std::uint32_t>(edges.size()));
  ChainPlan plan;
  plan_chains(edges, touched, plan);
  VertexNumbering numbering;
  number_vertices(edges, fragments, ranges, plan, numbering);
  merge_edges(edges, plan, numbering, g);
}

}  // namespace

void build_plane_graph(const EdgeList& edges, const std::vector<Fragment>& fragments,
                       const std::vector<std::uint8_t>& touched, PlaneGraph& g) {
  build_edges(edges, fragments, touched, g);
  plane_graph_build::order_around(g);
}

void build_plane_graph(const EdgeList& edges, Snapped& snapped, PlaneGraph& g) {
  build_edges(edges, snapped.fragments, snapped.touched, g);
  discard(snapped.fragments);
  discard(snapped.touched);
  plane_graph_build::order_around(g);
}

}  // namespace edgeland::detail
