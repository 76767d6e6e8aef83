#pragma once
// The noded fragments as a plane graph: integer vertices, undirected edges with net
// multiplicities per (channel, polygon), and half-edges sorted by angle around each vertex.
//
// An edge is a polyline. Fragments of untouched segments (Snapped::touched: nothing else
// meets them) are chained along their ring into one edge, so a long stretch of boundary that the
// operation does not touch costs the later stages one edge, not one per segment. Chain interior
// points meet nothing else, and no chain has an interior point smaller (lexicographically) than
// both its ends, so each connected component's smallest point is a graph vertex (labeling
// relies on it).
#include <cstdint>
#include <vector>

#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "input_edges.hpp"
#include "snap_rounding.hpp"

namespace edgeland::detail {

// Net multiplicity of one (channel, polygon) on an edge, counted along half-edge 2e.
struct Multiplicity {
  std::uint8_t channel;
  std::int32_t polygon;
  std::int32_t net;  // never 0 once the graph is built
};

// Its arrays are scratch storage (edgeland/kernel/scratch.hpp).
struct PlaneGraph {
  ScratchVector<Point64> vertices;  // sorted, unique
  // Edge e joins from(e) < to(e) (vertex ids, lexicographic). Half-edge 2e runs from -> to,
  // 2e + 1 runs to -> from; the twin of half-edge h is h ^ 1. Two edges may join the same two
  // vertices along different polylines. origin_of[h] is where half-edge h starts (so
  // origin_of[2e] = from(e), origin_of[2e + 1] = to(e)): one load, no branch, for the walks
  // of labeling and assembly that ask it at every step.
  ScratchVector<std::uint32_t> origin_of;
  // Interior points of a chain edge are read from the input segments, not copied: the points
  // of edge e are the starts of chain[e].count segments after chain[e].first along its ring
  // (ring [ring_begin, ring_begin + ring_len) of the segment list), in from -> to order unless
  // `reversed`. A fragment edge has count 0.
  struct Chain {
    std::uint32_t first = 0, count = 0, ring_begin = 0, ring_len = 1;
    bool reversed = false;
  };
  ScratchVector<Chain> chain;
  const std::vector<Segment>* segments = nullptr;
  ScratchVector<std::uint32_t> mult_begin;  // CSR into mults, size edges + 1
  ScratchVector<Multiplicity> mults;
  // Outgoing half-edges of vertex v, counter-clockwise from angle 0:
  // around[around_begin[v] .. around_begin[v + 1]). turn_at[h] is the position there, at h's
  // target, of the half-edge next clockwise from h's twin: the sharpest left turn after h (the
  // next half-edge of the face on h's left). Walks along faces take one load a step from it,
  // not a search round the vertex.
  ScratchVector<std::uint32_t> around_begin, around, turn_at;
  std::size_t cancelled_edges = 0;  // edges whose multiplicities summed to zero

  std::size_t edge_count() const { return origin_of.size() / 2; }
  std::uint32_t from(std::uint32_t e) const { return origin_of[2 * e]; }
  std::uint32_t to(std::uint32_t e) const { return origin_of[2 * e + 1]; }
  std::uint32_t origin(std::uint32_t h) const { return origin_of[h]; }
  std::uint32_t target(std::uint32_t h) const { return origin_of[h ^ 1]; }
  std::uint32_t interior_count(std::uint32_t e) const { return chain[e].count; }
  // Interior point i (0-based, from -> to) of edge e.
  Point64 interior_point(std::uint32_t e, std::uint32_t i) const {
    const Chain& c = chain[e];
    const std::uint32_t k = c.reversed ? c.count - i : i + 1;  // segments after `first`
    return (*segments)[c.ring_begin + (c.first - c.ring_begin + k) % c.ring_len].a;
  }
  // The point after the origin along half-edge h (its direction at the origin).
  Point64 first_step(std::uint32_t h) const {
    const std::uint32_t e = h >> 1;
    if (interior_count(e) == 0) return vertices[target(h)];
    return interior_point(e, (h & 1) ? interior_count(e) - 1 : 0);
  }
  // Appends the points of half-edge h from its origin up to, not including, its target.
  void append_points(std::uint32_t h, std::vector<Point64>& out) const;
};

// `fragments` lists the fragments of some segments (snap_round); a segment with none listed is
// its own single fragment. `edges` describes each input segment: its tag, the segment after it
// along its ring and its weight; `touched` whether it is touched (Snapped::touched; an
// untouched segment is its own single fragment).
// O(f) for the f fragments of touched segments (radix sorts), plus O(n) for the rest. Builds
// into g, reusing its arrays' capacity.
void build_plane_graph(const EdgeList& edges, const std::vector<Fragment>& fragments,
                       const std::vector<std::uint8_t>& touched, PlaneGraph& g);
// The same from snap rounding's result, whose fragments and touched flags it consumes: they are
// discarded (scratch.hpp) once read, before the angular sort (the pipeline, run()).
void build_plane_graph(const EdgeList& edges, Snapped& snapped, PlaneGraph& g);

}  // namespace edgeland::detail
