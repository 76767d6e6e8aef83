#include "input_edges.hpp"

namespace edgeland::detail {

void append_ring_edges(const std::vector<Ring>& rings, std::uint8_t channel, bool tag_polygons,
                       std::vector<TaggedSegment>& out) {
  for (std::size_t p = 0; p < rings.size(); ++p) {
    const Ring& ring = rings[p];
    const std::uint32_t first = static_cast<std::uint32_t>(out.size());
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Segment s = ring_edge(ring, i);
      if (s.a == s.b) continue;
      const std::uint32_t at = static_cast<std::uint32_t>(out.size());
      out.push_back({s, channel, tag_polygons ? static_cast<std::int32_t>(p) : 0, at + 1});
    }
    if (out.size() > first) out.back().next = first;
  }
}

}  // namespace edgeland::detail
