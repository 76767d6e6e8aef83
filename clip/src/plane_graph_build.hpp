#pragma once
// The steps of build_plane_graph (plane_graph.hpp), each handing the next a typed result:
//   chain_plan       which segments become edges alone (touched) and which are chained;
//   number_vertices  every vertex occurrence (starts of pieces and chains, open ends) sorted
//                    once, which numbers the vertices and gives each piece its end ids;
//   merge_edges      pieces with equal ends merged into one edge, multiplicities summed per
//                    (operand, polygon); chains appended (nothing coincides with a chain);
//   order_around     half-edges sorted by angle round each vertex, with turn_at.
// Internal to the plane graph's sources.
#include <cstdint>
#include <vector>

#include "edgeland/kernel/scratch.hpp"
#include "input_edges.hpp"
#include "plane_graph.hpp"
#include "snap_rounding.hpp"

namespace edgeland::detail::plane_graph_build {

inline constexpr std::uint32_t kNoOccurrence = 0xffffffffu;

// The listed fragments of each segment (snap_round lists them in segment order); a segment with
// none listed is its own single fragment.
class FragmentRanges {
 public:
  FragmentRanges(const std::vector<Fragment>& fragments, std::uint32_t segment_count);
  bool listed(std::uint32_t s) const { return first_[s] != first_[s + 1]; }
  std::uint32_t first(std::uint32_t s) const { return first_[s]; }
  std::uint32_t last(std::uint32_t s) const { return first_[s + 1]; }  // one past
  // How many graph pieces segment s yields.
  std::uint32_t piece_count(std::uint32_t s) const { return listed(s) ? last(s) - first(s) : 1; }

 private:
  ScratchVector<std::uint32_t> first_;
};

// Step 1. Untouched segments are chained along their ring (plane_graph.hpp says why and where
// chains are cut); touched segments become pieces, one per fragment.
struct ChainPlan {
  ScratchVector<PlaneGraph::Chain> chains;  // by first segment
  ScratchVector<std::uint32_t> touched;     // touched segments, increasing
};
void plan_chains(const EdgeList& edges, const std::vector<std::uint8_t>& touched, ChainPlan& plan);

// One fragment of a touched segment as an undirected edge between vertex ids.
struct FragmentEdge {
  std::uint32_t lo, hi;  // vertex ids, lo < hi
  std::int32_t polygon;
  std::uint8_t channel;
  std::int32_t net;  // the segment's weight, negated when the fragment runs hi -> lo
};

// Step 2. Vertex ids, increasing in the points' lexicographic order, and every piece's ends.
struct VertexNumbering {
  ScratchVector<std::uint64_t> keys;              // vertex id -> point key (point_key.hpp)
  ScratchVector<std::uint32_t> vertex_of;         // occurrence -> id
  ScratchVector<std::uint32_t> first_occurrence;  // of s's start
  // Of segment s's end when its ring successor starts elsewhere (an open run's end); empty when
  // no segment has one.
  ScratchVector<std::uint32_t> own_end;
  ScratchVector<FragmentEdge> pieces;  // touched segments' fragments

  // The vertex where segment s ends: where the segment after it along its ring starts.
  std::uint32_t end_vertex(std::uint32_t s, const std::vector<std::uint32_t>& next) const;
  std::uint32_t start_vertex(std::uint32_t s) const { return vertex_of[first_occurrence[s]]; }
};
void number_vertices(const EdgeList& edges, const std::vector<Fragment>& fragments,
                     const FragmentRanges& ranges, const ChainPlan& plan, VertexNumbering& out);

// Step 3. g's vertices, edges, chains and multiplicities (g's arrays keep their capacity).
void merge_edges(const EdgeList& edges, const ChainPlan& plan, VertexNumbering& numbering,
                 PlaneGraph& g);

// Step 4. g.around_begin, g.around and g.turn_at.
void order_around(PlaneGraph& g);

}  // namespace edgeland::detail::plane_graph_build
