#pragma once
// Is a peer's result, converted back to integers, a valid input for the next operation?
//
// Exactly what is checked (bench/README.md repeats this):
//  * no holes: the outer rings as one edgeland PolygonSet must pass edgeland::validate
//    (every ring strictly simple, CCW after conversion, >= 3 distinct consecutive vertices,
//    in range; interiors pairwise disjoint);
//  * with holes: every ring, outer or hole, must pass edgeland::validate as a single polygon,
//    and every pair of distinct rings must have boundaries that neither cross (properly, or
//    at a shared point where one ring passes from one side of the other to the other side)
//    nor overlap along a segment; touching at isolated points is allowed (OGC). Which hole
//    belongs to which shell, and whether holes lie inside their shell, is not checked.
// edgeland's own results never have holes and take the first branch.
// O(n log n + pairs of edges with overlapping x-ranges); fine for the benchmark's shapes.
#include <string>

#include "peer.hpp"

namespace edgeland::bench {

struct RingCheck {
  bool ok = true;
  std::string failure;  // the first problem found, one line; empty when ok
};

RingCheck check_rings(const PeerRings& rings);

// The rings with repeated consecutive vertices merged (first and last included) and rings
// left with fewer than 3 vertices dropped: the lenient variant of the carving check, which
// separates vertices that merely round onto one integer point from real crossings.
PeerRings without_repeated_vertices(PeerRings rings);

}  // namespace edgeland::bench
