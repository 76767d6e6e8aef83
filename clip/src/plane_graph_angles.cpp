// build_plane_graph, step 4: half-edges in angular order round each vertex
// (plane_graph_build.hpp). Each half-edge's direction is read once (first_step walks chain
// indirections); most vertices have two to four half-edges.
#include <algorithm>

#include "edgeland/kernel/angle.hpp"
#include "offsets.hpp"
#include "plane_graph_build.hpp"

namespace edgeland::detail::plane_graph_build {
namespace {

// A half-edge leaving a vertex, with the direction of its first step.
struct Out {
  Point64 d;
  std::uint32_t h;
};

// Vertices of at most this degree (most of them) get their half-edges placed by rank.
constexpr std::uint32_t kRankedDegree = 4;

// Sorts [first, last) stably: by insertion when it is short, by merge sort otherwise. For the
// half-edges round vertices of degree above kRankedDegree (below: place_by_rank).
template <class It, class Less>
void sort_short_run(It first, It last, Less less) {
  if (last - first > 16) {
    std::stable_sort(first, last, less);
    return;
  }
  for (It i = first; i != last; ++i) {
    const auto x = *i;
    It j = i;
    for (; j != first && less(x, *(j - 1)); --j) *j = *(j - 1);
    *j = x;
  }
}

// Writes the n <= kRankedDegree half-edges of one vertex (out[0 .. n), starting at position b
// of g.around) in counter-clockwise order: each one's place is the number of others before it,
// every pair compared once (a tie, which a plane graph never has, keeps the listed order), so
// the ranks are a permutation and no branch depends on a comparison: mispredicted branches
// were most of the angle sort.
void place_by_rank(const Out* out, std::uint32_t n, std::uint32_t b, PlaneGraph& g) {
  std::uint32_t rank[kRankedDegree] = {};
  for (std::uint32_t i = 1; i < n; ++i)
    for (std::uint32_t j = 0; j < i; ++j) {
      const std::uint32_t i_first = angle_less_branch_free(out[i].d, out[j].d);
      rank[j] += i_first;
      rank[i] += 1 - i_first;
    }
  for (std::uint32_t k = 0; k < n; ++k) {
    g.around[b + rank[k]] = out[k].h;
    g.turn_at[out[k].h ^ 1] = b + rank[k] - 1 + (rank[k] == 0 ? n : 0);
  }
}

// The same for a vertex of higher degree, by sorting: out[0 .. e - b) becomes around[b .. e).
void place_by_sort(Out* out, std::uint32_t b, std::uint32_t e, PlaneGraph& g) {
  sort_short_run(out, out + (e - b),
                 [](const Out& x, const Out& y) { return angle_less(x.d, y.d); });
  for (std::uint32_t k = b; k < e; ++k) {
    g.around[k] = out[k - b].h;
    g.turn_at[out[k - b].h ^ 1] = k == b ? e - 1 : k - 1;
  }
}

// g.around_begin: the offsets of each vertex's half-edges.
void count_around(PlaneGraph& g) {
  g.around_begin.assign(g.vertices.size() + 1, 0);
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    ++g.around_begin[g.from(e) + 1];
    ++g.around_begin[g.to(e) + 1];
  }
  add_up_counts(g.around_begin);
}

// g.around before the sort: every half-edge, grouped by origin as around_begin says, in edge
// order within a group.
void group_by_origin(PlaneGraph& g) {
  g.around.resize(2 * g.edge_count());
  ScratchVector<std::uint32_t> fill;
  fill.assign(g.around_begin.begin(), g.around_begin.end() - 1);
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    g.around[fill[g.from(e)]++] = 2 * e;
    g.around[fill[g.to(e)]++] = 2 * e + 1;
  }
}

// The half-edges at around[b .. e), all leaving vertex v, with the directions of their first
// steps, into out[0 .. e - b).
void first_steps(const PlaneGraph& g, std::uint32_t v, std::uint32_t b, std::uint32_t e, Out* out) {
  const Point64 p = g.vertices[v];
  for (std::uint32_t k = b; k < e; ++k) {
    const Point64 step = g.first_step(g.around[k]);
    out[k - b] = {{step.x - p.x, step.y - p.y}, g.around[k]};
  }
}

}  // namespace

// The directions are read one vertex at a time, into a buffer of one vertex's half-edges: a
// direction per half-edge for the whole graph (24 bytes each) was the largest array of the
// plane graph's build, alive beside all of the graph (issue 28: 18 of 111 MB at combs of
// 10^5 vertices, the peak).
void order_around(PlaneGraph& g) {
  count_around(g);
  group_by_origin(g);
  g.turn_at.resize(g.around.size());
  ScratchVector<Out> out;
  for (std::uint32_t v = 0; v < g.vertices.size(); ++v) {
    const std::uint32_t b = g.around_begin[v], e = g.around_begin[v + 1];
    if (out.size() < e - b) out.resize(e - b);
    first_steps(g, v, b, e, out.data());
    if (e - b <= kRankedDegree) {
      place_by_rank(out.data(), e - b, b, g);
    } else {
      place_by_sort(out.data(), b, e, g);
    }
  }
}

}  // namespace edgeland::detail::plane_graph_build
