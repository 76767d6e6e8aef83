#include "planar_graph.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "edgeland/kernel/angle.hpp"

namespace edgeland::detail {
namespace {

struct Piece {
  Point64 lo, hi;  // lo < hi
  std::uint8_t channel;
  std::int32_t polygon;
  std::int32_t sign;  // +1 when the fragment runs lo -> hi
};

std::uint32_t vertex_id(const std::vector<Point64>& vs, Point64 p) {
  return static_cast<std::uint32_t>(std::lower_bound(vs.begin(), vs.end(), p) - vs.begin());
}

}  // namespace

void PlaneGraph::append_points(std::uint32_t h, std::vector<Point64>& out) const {
  const std::uint32_t e = h >> 1;
  out.push_back(vertices[origin(h)]);
  if (h & 1)
    out.insert(out.end(), interior.rbegin() + (interior.size() - interior_begin[e + 1]),
               interior.rbegin() + (interior.size() - interior_begin[e]));
  else
    out.insert(out.end(), interior.begin() + interior_begin[e],
               interior.begin() + interior_begin[e + 1]);
}

PlaneGraph build_plane_graph(const std::vector<Fragment>& fragments,
                             const std::vector<std::uint8_t>& channel_of,
                             const std::vector<std::int32_t>& polygon_of,
                             const std::vector<std::uint32_t>& next,
                             const std::vector<bool>& touched) {
  const std::uint32_t n = static_cast<std::uint32_t>(next.size());
  // Fragments come in segment order, at least one per segment; an untouched segment has one.
  std::vector<std::uint32_t> first_fragment(n + 1, 0);
  for (const Fragment& f : fragments) ++first_fragment[f.parent + 1];
  for (std::uint32_t s = 0; s < n; ++s) first_fragment[s + 1] += first_fragment[s];
  auto piece_of = [&](std::uint32_t s) -> const Segment& { return fragments[first_fragment[s]].seg; };

  // Where chains of untouched segments start: after a touched segment, at the ring's smallest
  // vertex, and, for a ring nothing touches, also halfway round (no edge may be a loop).
  std::vector<bool> starts_chain(n, false);
  for (std::uint32_t b = 0; b < n;) {
    std::uint32_t e = b;
    while (next[e] == e + 1) ++e;  // the ring occupies [b, e], next[e] == b
    const std::uint32_t len = e - b + 1;
    std::uint32_t smallest = b;
    bool all_untouched = true;
    for (std::uint32_t s = b; s <= e; ++s) {
      if (piece_of(s).a < piece_of(smallest).a) smallest = s;
      all_untouched = all_untouched && !touched[s];
    }
    for (std::uint32_t s = b; s <= e; ++s) {
      const std::uint32_t prev = s == b ? e : s - 1;
      if (!touched[s] && (touched[prev] || s == smallest)) starts_chain[s] = true;
    }
    if (all_untouched) starts_chain[b + (smallest - b + len / 2) % len] = true;
    b = e + 1;
  }

  std::vector<Piece> pieces;
  PlaneGraph g;
  for (std::uint32_t s = 0; s < n; ++s) {
    if (!touched[s]) {
      if (starts_chain[s]) g.vertices.push_back(piece_of(s).a);
      continue;
    }
    for (std::uint32_t k = first_fragment[s]; k < first_fragment[s + 1]; ++k) {
      const Fragment& f = fragments[k];
      const bool forward = f.seg.a < f.seg.b;
      pieces.push_back({forward ? f.seg.a : f.seg.b, forward ? f.seg.b : f.seg.a,
                        channel_of[s], polygon_of[s], forward ? 1 : -1});
      g.vertices.push_back(f.seg.a);
      g.vertices.push_back(f.seg.b);
    }
  }
  std::sort(pieces.begin(), pieces.end(), [](const Piece& x, const Piece& y) {
    return std::tie(x.lo, x.hi, x.channel, x.polygon) < std::tie(y.lo, y.hi, y.channel, y.polygon);
  });
  std::sort(g.vertices.begin(), g.vertices.end());
  g.vertices.erase(std::unique(g.vertices.begin(), g.vertices.end()), g.vertices.end());

  // Merge pieces with equal endpoints, summing multiplicities per (channel, polygon).
  g.mult_begin.push_back(0);
  g.interior_begin.push_back(0);
  for (std::size_t i = 0; i < pieces.size();) {
    std::size_t j = i;
    const std::size_t first_mult = g.mults.size();
    while (j < pieces.size() && pieces[j].lo == pieces[i].lo && pieces[j].hi == pieces[i].hi) {
      std::size_t k = j;
      std::int32_t net = 0;
      while (k < pieces.size() && pieces[k].lo == pieces[j].lo && pieces[k].hi == pieces[j].hi &&
             pieces[k].channel == pieces[j].channel && pieces[k].polygon == pieces[j].polygon) {
        net += pieces[k].sign;
        ++k;
      }
      if (net != 0) g.mults.push_back({pieces[j].channel, pieces[j].polygon, net});
      j = k;
    }
    if (g.mults.size() == first_mult) {
      ++g.cancelled_edges;
    } else {
      g.from.push_back(vertex_id(g.vertices, pieces[i].lo));
      g.to.push_back(vertex_id(g.vertices, pieces[i].hi));
      g.mult_begin.push_back(static_cast<std::uint32_t>(g.mults.size()));
      g.interior_begin.push_back(static_cast<std::uint32_t>(g.interior.size()));
    }
    i = j;
  }

  // Chains: nothing else meets an untouched segment, so no other edge can coincide with one.
  for (std::uint32_t s = 0; s < n; ++s) {
    if (!starts_chain[s]) continue;
    const std::size_t mark = g.interior.size();
    std::uint32_t last = s;
    for (std::uint32_t t = next[s]; !touched[t] && !starts_chain[t]; t = next[t]) {
      g.interior.push_back(piece_of(t).a);
      last = t;
    }
    std::uint32_t a = vertex_id(g.vertices, piece_of(s).a), b = vertex_id(g.vertices, piece_of(last).b);
    if (a == b || b == g.vertices.size() || g.vertices[b] != piece_of(last).b)
      throw std::logic_error("plane graph: a chain does not end at a vertex");
    std::int32_t net = 1;
    if (b < a) {
      std::swap(a, b);
      std::reverse(g.interior.begin() + static_cast<std::ptrdiff_t>(mark), g.interior.end());
      net = -1;
    }
    g.from.push_back(a);
    g.to.push_back(b);
    g.mults.push_back({channel_of[s], polygon_of[s], net});
    g.mult_begin.push_back(static_cast<std::uint32_t>(g.mults.size()));
    g.interior_begin.push_back(static_cast<std::uint32_t>(g.interior.size()));
  }

  // Half-edges around each vertex, sorted by the angle of their first step.
  const std::size_t nv = g.vertices.size(), nh = 2 * g.edge_count();
  g.around_begin.assign(nv + 1, 0);
  for (std::uint32_t h = 0; h < nh; ++h) ++g.around_begin[g.origin(h) + 1];
  for (std::size_t v = 0; v < nv; ++v) g.around_begin[v + 1] += g.around_begin[v];
  g.around.resize(nh);
  std::vector<std::uint32_t> fill(g.around_begin.begin(), g.around_begin.end() - 1);
  for (std::uint32_t h = 0; h < nh; ++h) g.around[fill[g.origin(h)]++] = h;
  g.position_of.resize(nh);
  for (std::size_t v = 0; v < nv; ++v) {
    const Point64 o = g.vertices[v];
    auto first = g.around.begin() + g.around_begin[v], last = g.around.begin() + g.around_begin[v + 1];
    std::sort(first, last, [&](std::uint32_t h1, std::uint32_t h2) {
      const Point64 a = g.first_step(h1), b = g.first_step(h2);
      return angle_less({a.x - o.x, a.y - o.y}, {b.x - o.x, b.y - o.y});
    });
    for (std::uint32_t k = g.around_begin[v]; k < g.around_begin[v + 1]; ++k)
      g.position_of[g.around[k]] = k;
  }
  return g;
}

}  // namespace edgeland::detail
