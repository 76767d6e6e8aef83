#pragma once
// The noded fragments as a plane graph: integer vertices, undirected edges with net
// multiplicities per (channel, polygon), and half-edges sorted by angle around each vertex.
#include <cstdint>
#include <vector>

#include "edgeland/kernel/point.hpp"
#include "snap_rounding.hpp"

namespace edgeland::detail {

// Net multiplicity of one (channel, polygon) on an edge, counted along half-edge 2e.
struct Multiplicity {
  std::uint8_t channel;
  std::int32_t polygon;
  std::int32_t net;  // never 0 once the graph is built
};

struct PlaneGraph {
  std::vector<Point64> vertices;               // sorted, unique
  // Edge e joins from[e] < to[e] (vertex ids, lexicographic). Half-edge 2e runs from -> to,
  // 2e + 1 runs to -> from; the twin of half-edge h is h ^ 1.
  std::vector<std::uint32_t> from, to;
  std::vector<std::uint32_t> mult_begin;       // CSR into mults, size edges + 1
  std::vector<Multiplicity> mults;
  // Outgoing half-edges of vertex v, counter-clockwise from angle 0:
  // around[around_begin[v] .. around_begin[v + 1]); position_of[h] indexes into it.
  std::vector<std::uint32_t> around_begin, around, position_of;
  std::size_t cancelled_edges = 0;             // edges whose multiplicities summed to zero

  std::size_t edge_count() const { return from.size(); }
  std::uint32_t origin(std::uint32_t h) const { return (h & 1) ? to[h >> 1] : from[h >> 1]; }
  std::uint32_t target(std::uint32_t h) const { return origin(h ^ 1); }
};

// `channel_of` / `polygon_of` give the tag of each input segment (Fragment::parent).
PlaneGraph build_plane_graph(const std::vector<Fragment>& fragments,
                             const std::vector<std::uint8_t>& channel_of,
                             const std::vector<std::int32_t>& polygon_of);

}  // namespace edgeland::detail
