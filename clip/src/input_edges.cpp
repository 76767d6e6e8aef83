#include "input_edges.hpp"

namespace edgeland::detail {

void append_ring_edges(const std::vector<Ring>& rings, std::uint8_t channel, bool tag_polygons,
                       EdgeList& out, const std::vector<std::uint32_t>* which) {
  const std::size_t count = which ? which->size() : rings.size();
  std::size_t total = out.size();
  for (std::size_t k = 0; k < count; ++k) total += rings[which ? (*which)[k] : k].size();
  out.segments.reserve(total);
  out.channel.reserve(total);
  out.polygon.reserve(total);
  out.next.reserve(total);
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t p = which ? (*which)[k] : k;
    const Ring& ring = rings[p];
    const std::int32_t tag = tag_polygons ? static_cast<std::int32_t>(p) : 0;
    const std::uint32_t first = static_cast<std::uint32_t>(out.size());
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Segment s = ring_edge(ring, i);
      if (s.a == s.b) continue;
      out.next.push_back(static_cast<std::uint32_t>(out.size()) + 1);
      out.segments.push_back(s);
      out.channel.push_back(channel);
      out.polygon.push_back(tag);
    }
    if (out.size() > first) out.next.back() = first;
  }
}

}  // namespace edgeland::detail
