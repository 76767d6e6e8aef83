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

// The same for a vertex of higher degree, by sorting: out[b .. e) becomes around[b .. e).
void place_by_sort(Out* out, std::uint32_t b, std::uint32_t e, PlaneGraph& g) {
  sort_short_run(out + b, out + e, [](const Out& x, const Out& y) { return angle_less(x.d, y.d); });
  for (std::uint32_t k = b; k < e; ++k) {
    g.around[k] = out[k].h;
    g.turn_at[out[k].h ^ 1] = k == b ? e - 1 : k - 1;
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

// Every half-edge with the direction of its first step, grouped by origin as around_begin says.
void first_steps(const PlaneGraph& g, std::vector<Out>& out) {
  out.resize(2 * g.edge_count());
  ScratchVector<std::uint32_t> fill;
  fill.assign(g.around_begin.begin(), g.around_begin.end() - 1);
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const std::uint32_t a = g.from(e), b = g.to(e);
    const Point64 pa = g.vertices[a], pb = g.vertices[b];
    const std::uint32_t m = g.chain[e].count;
    const Point64 step_a = m == 0 ? pb : g.interior_point(e, 0);
    const Point64 step_b = m == 0 ? pa : g.interior_point(e, m - 1);
    out[fill[a]++] = {{step_a.x - pa.x, step_a.y - pa.y}, 2 * e};
    out[fill[b]++] = {{step_b.x - pb.x, step_b.y - pb.y}, 2 * e + 1};
  }
}

}  // namespace

void order_around(PlaneGraph& g) {
  count_around(g);
  ScratchVector<Out> out;
  first_steps(g, out);
  g.around.resize(out.size());
  g.turn_at.resize(out.size());
  for (std::size_t v = 0; v < g.vertices.size(); ++v) {
    const std::uint32_t b = g.around_begin[v], e = g.around_begin[v + 1];
    if (e - b <= kRankedDegree) {
      place_by_rank(out.data() + b, e - b, b, g);
    } else {
      place_by_sort(out.data(), b, e, g);
    }
  }
}

}  // namespace edgeland::detail::plane_graph_build
