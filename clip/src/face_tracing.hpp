#pragma once
// Faces of directed edges that meet only at shared endpoints, traced by the sharpest-left-turn
// rule of assembly (thesis 3.5.2): hole splitting's pieces (ring edges plus bridges both ways)
// and merged tiles' boundaries (merge_tiles.cpp).
#include <vector>

#include "assembly.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// The faces left of `edges` (each with the inside on its left), traced by turning, at the end of
// an edge, clockwise from its reverse to the first edge leaving there. Each edge is walked
// once; walks revisiting a point are split there. Appends the faces to `out`: counter-clockwise
// rings bound faces from outside, clockwise ones are holes. O(n log n).
void trace_faces(const std::vector<Segment>& edges, std::vector<ScratchRing>& out);

}  // namespace edgeland::detail
