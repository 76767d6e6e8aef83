// build_plane_graph, step 3: edges and their multiplicities (plane_graph_build.hpp).
#include <algorithm>
#include <tuple>

#include "edgeland/kernel/assert.hpp"
#include "plane_graph_build.hpp"
#include "point_key.hpp"
#include "radix_sort.hpp"

namespace edgeland::detail::plane_graph_build {
namespace {

constexpr const char* kStage = "plane graph";

// Writes edges and multiplicities by index into arrays sized for the most edges there can be,
// then trims them: one store per field instead of a capacity check per push.
class EdgeWriter {
 public:
  EdgeWriter(PlaneGraph& g, std::size_t edge_bound) : g_(g) {
    g.origin_of.resize(2 * edge_bound);
    g.mult_begin.resize(edge_bound + 1);
    g.mults.resize(edge_bound);
    g.mult_begin[0] = 0;
  }
  std::uint32_t mult_count() const { return mults_; }
  void add_mult(std::uint8_t channel, std::int32_t polygon, std::int32_t net) {
    g_.mults[mults_++] = {channel, polygon, net};
  }
  // Closes edge lo-hi, whose multiplicities start at first_mult; with none, it cancelled.
  void close_edge(std::uint32_t lo, std::uint32_t hi, std::uint32_t first_mult) {
    if (mults_ == first_mult) {
      ++g_.cancelled_edges;
      return;
    }
    g_.origin_of[2 * edges_] = lo;
    g_.origin_of[2 * edges_ + 1] = hi;
    g_.mult_begin[++edges_] = mults_;
  }
  std::uint32_t edges() const { return edges_; }
  void trim() {
    g_.origin_of.resize(2 * std::size_t{edges_});
    g_.mult_begin.resize(edges_ + 1);
    g_.mults.resize(mults_);
  }

 private:
  PlaneGraph& g_;
  std::uint32_t edges_ = 0, mults_ = 0;
};

// The pieces [first, last) join the same two vertices: their nets summed per (channel, polygon).
// They come in segment order, which is already (channel, polygon) order for clip's operands (the
// sorts are stable); a group that is not (hole splitting's bridges) is put in order first.
void merge_group(FragmentEdge* first, FragmentEdge* last, EdgeWriter& out) {
  auto tag_less = [](const FragmentEdge& x, const FragmentEdge& y) {
    return std::tie(x.channel, x.polygon) < std::tie(y.channel, y.polygon);
  };
  if (!std::is_sorted(first, last, tag_less)) std::stable_sort(first, last, tag_less);
  for (FragmentEdge* k = first; k != last;) {
    FragmentEdge* m = k;
    std::int32_t net = 0;
    for (; m != last && m->channel == k->channel && m->polygon == k->polygon; ++m) net += m->net;
    if (net != 0) out.add_mult(k->channel, k->polygon, net);
    k = m;
  }
}

// Pieces sorted by (lo, hi), stably: two counting sorts (vertex ids are small), by hi and then
// by lo. (Sorting each lo's short run by hi instead branched unpredictably on every piece.)
// Most edges have one piece: written straight out.
void add_piece_edges(std::vector<FragmentEdge>& pieces, std::size_t vertex_count, EdgeWriter& out) {
  counting_sort(pieces, vertex_count, [](const FragmentEdge& p) { return p.hi; });
  counting_sort(pieces, vertex_count, [](const FragmentEdge& p) { return p.lo; });
  for (std::size_t i = 0; i < pieces.size();) {
    const std::uint32_t lo = pieces[i].lo, hi = pieces[i].hi;
    std::size_t j = i + 1;
    while (j < pieces.size() && pieces[j].lo == lo && pieces[j].hi == hi) ++j;
    const std::uint32_t first_mult = out.mult_count();
    if (j > i + 1) {
      merge_group(pieces.data() + i, pieces.data() + j, out);
    } else if (pieces[i].net != 0) {  // (a merged stretch of weight 0 cancels alone)
      out.add_mult(pieces[i].channel, pieces[i].polygon, pieces[i].net);
    }
    out.close_edge(lo, hi, first_mult);
    i = j;
  }
}

// Chains: nothing else meets an untouched segment, so no other edge can coincide with one.
void add_chain_edges(const EdgeList& edges, const ChainPlan& plan, const VertexNumbering& numbering,
                     EdgeWriter& out, std::vector<PlaneGraph::Chain>& chains) {
  for (PlaneGraph::Chain c : plan.chains) {
    const std::uint32_t last = c.ring_begin + (c.first - c.ring_begin + c.count) % c.ring_len;
    std::uint32_t a = numbering.start_vertex(c.first), b = numbering.end_vertex(last, edges.next);
    if (a == b) fail_stage(kStage, "a chain is a loop");
    std::int32_t net = edges.weight_of(c.first);
    if (b < a) {
      std::swap(a, b);
      c.reversed = true;
      net = -net;
    }
    // (Only merged stretches weigh 0, and they are never chained.)
    if (net == 0) fail_stage(kStage, "a chain of weight 0");
    out.add_mult(edges.channel[c.first], edges.polygon[c.first], net);
    out.close_edge(a, b, out.mult_count() - 1);
    chains.push_back(c);
  }
}

}  // namespace

void merge_edges(const EdgeList& edges, const ChainPlan& plan, VertexNumbering& numbering,
                 PlaneGraph& g) {
  // Every array of g is sized or cleared here (g may be built into again).
  g.chain.clear();
  g.cancelled_edges = 0;
  const std::size_t edge_bound = numbering.pieces.size() + plan.chains.size();
  g.chain.reserve(edge_bound);
  g.vertices.resize(numbering.keys.size());
  for (std::size_t i = 0; i < numbering.keys.size(); ++i)
    g.vertices[i] = point_of(numbering.keys[i]);
  g.segments = &edges.segments;
  EdgeWriter out(g, edge_bound);
  add_piece_edges(numbering.pieces, numbering.keys.size(), out);
  g.chain.resize(out.edges());  // fragment edges: count 0
  add_chain_edges(edges, plan, numbering, out, g.chain);
  out.trim();
}

}  // namespace edgeland::detail::plane_graph_build
