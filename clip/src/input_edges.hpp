#pragma once
// Edge collection: the operands as one list of directed, tagged integer segments.
#include <cstdint>
#include <vector>

#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// A directed input edge. Its left side is the inside of `polygon` of operand `channel`
// (for normalize: it adds +1 to the winding number on its left).
struct TaggedSegment {
  Segment seg;
  std::uint8_t channel = 0;  // 0 = subject / normalize rings, 1 = clip operand
  std::int32_t polygon = 0;  // index within its operand
  std::uint32_t next = 0;    // index (in the same list) of the edge that follows along the ring
};

// Appends the edges of every ring, ring after ring, each ring's edges in order; zero-length
// edges (repeated points) are skipped.
void append_ring_edges(const std::vector<Ring>& rings, std::uint8_t channel, bool tag_polygons,
                       std::vector<TaggedSegment>& out);

}  // namespace edgeland::detail
