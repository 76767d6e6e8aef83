#pragma once
// Assembly (thesis 3.5): the operation table picks the result label of every face, and the
// boundary of every labeled region is traced with the sharpest-left-turn rule (3.5.2).
#include <cstdint>
#include <utility>
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "face_label.hpp"
#include "labeling.hpp"
#include "plane_graph.hpp"

namespace edgeland::detail {

// A ring in scratch storage (scratch.hpp): the rings of a region with holes are read by hole
// splitting and then dropped (its pieces are new rings).
using ScratchRing = ScratchVector<Point64>;

// The boundary of one labeled region, split into simple loops.
struct RegionRings {
  FaceLabel label = -1;
  ScratchVector<ScratchRing> outers;  // counter-clockwise
  ScratchVector<ScratchRing> holes;   // clockwise
};

// The assembled result: the rings of regions without holes, each a counter-clockwise output
// polygon in canonical form (canonical.hpp; only their order is left to do), and the regions
// with holes (sorted by label) for hole splitting. Loops that revisit a vertex are split there,
// so every ring is a simple closed polyline of graph edges. collinear_free_operands: no input
// ring has collinear consecutive vertices, so only graph vertices can be collinear.
// labels[i] is the label of rings[i]. corner_bridges: the rings of a region with holes keep only
// the points hole splitting may bridge to whatever the region's history: its corners and the
// points where two of its rings touch (without it, every graph vertex on them stays, and which
// vertices the graph has depends on the operands, not only on the region).
struct Assembled {
  std::vector<Ring> rings;
  ScratchVector<FaceLabel> labels;
  ScratchVector<RegionRings> holed;
};
Assembled assemble(const PlaneGraph& g, const std::vector<SideState>& left, const LabelOf& label_of,
                   bool collinear_free_operands, bool corner_bridges = false);

// Closed walks along the half-edges with emitted[h] >= 0, each following the sharpest left
// turn among half-edges of its own label, in a fixed order. Flat: walk i is
// half_edges[begin[i] .. begin[i + 1]) with label[i] (one allocation per array, not per walk);
// revisits[i]: whether walk i leaves some vertex twice (then it is several loops).
struct BoundaryWalks {
  ScratchVector<FaceLabel> label;
  ScratchVector<std::uint8_t> revisits;
  ScratchVector<std::uint32_t> begin;  // starts with 0
  ScratchVector<std::uint32_t> half_edges;
  std::size_t size() const { return label.size(); }
  const std::uint32_t* first(std::size_t i) const { return half_edges.data() + begin[i]; }
  const std::uint32_t* last(std::size_t i) const { return half_edges.data() + begin[i + 1]; }
};
BoundaryWalks trace_boundaries(const PlaneGraph& g, const std::vector<FaceLabel>& emitted);

// Splits the closed half-edge walk [first, last) where it revisits a vertex (an origin) into
// loops that visit each vertex once. scratch_position: one -1 per vertex, restored on return.
std::vector<std::vector<std::uint32_t>> split_at_repeated_vertices(
    const PlaneGraph& g, const std::uint32_t* first, const std::uint32_t* last,
    std::vector<std::int32_t>& scratch_position);

// The ring of points along the half-edges [first, last), allocated once at its final size.
Ring ring_along(const PlaneGraph& g, const std::uint32_t* first, const std::uint32_t* last);
// The same, into `ring` (cleared first).
void ring_along_into(const PlaneGraph& g, const std::uint32_t* first, const std::uint32_t* last,
                     std::vector<Point64>& ring);

}  // namespace edgeland::detail
