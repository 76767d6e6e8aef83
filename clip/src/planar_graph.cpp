#include "planar_graph.hpp"

#include <algorithm>
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

PlaneGraph build_plane_graph(const std::vector<Fragment>& fragments,
                             const std::vector<std::uint8_t>& channel_of,
                             const std::vector<std::int32_t>& polygon_of) {
  std::vector<Piece> pieces;
  pieces.reserve(fragments.size());
  for (const Fragment& f : fragments) {
    const bool forward = f.seg.a < f.seg.b;
    pieces.push_back({forward ? f.seg.a : f.seg.b, forward ? f.seg.b : f.seg.a,
                      channel_of[f.parent], polygon_of[f.parent], forward ? 1 : -1});
  }
  std::sort(pieces.begin(), pieces.end(), [](const Piece& x, const Piece& y) {
    return std::tie(x.lo, x.hi, x.channel, x.polygon) < std::tie(y.lo, y.hi, y.channel, y.polygon);
  });

  PlaneGraph g;
  g.vertices.reserve(2 * pieces.size());
  for (const Piece& p : pieces) {
    g.vertices.push_back(p.lo);
    g.vertices.push_back(p.hi);
  }
  std::sort(g.vertices.begin(), g.vertices.end());
  g.vertices.erase(std::unique(g.vertices.begin(), g.vertices.end()), g.vertices.end());

  // Merge pieces with equal endpoints, summing multiplicities per (channel, polygon).
  g.mult_begin.push_back(0);
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
    }
    i = j;
  }

  // Half-edges around each vertex, sorted by angle.
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
      const Point64 a = g.vertices[g.target(h1)], b = g.vertices[g.target(h2)];
      return angle_less({a.x - o.x, a.y - o.y}, {b.x - o.x, b.y - o.y});
    });
    for (std::uint32_t k = g.around_begin[v]; k < g.around_begin[v + 1]; ++k)
      g.position_of[g.around[k]] = k;
  }
  return g;
}

}  // namespace edgeland::detail
