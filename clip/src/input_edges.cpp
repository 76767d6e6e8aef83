#include "input_edges.hpp"

namespace edgeland::detail {

void append_ring_edges(const std::vector<Ring>& rings, std::uint8_t channel, bool tag_polygons,
                       EdgeList& out, const std::vector<std::uint32_t>* which) {
  const std::size_t count = which ? which->size() : rings.size();
  std::uint32_t at = static_cast<std::uint32_t>(out.size());
  std::size_t total = out.size();
  for (std::size_t k = 0; k < count; ++k) total += rings[which ? (*which)[k] : k].size();
  // Sized once and written by index: the hot loop of small operations and of large smooth ones
  // alike, where four push_backs per edge cost more than the copying.
  out.segments.resize(total);
  out.channel.resize(total, channel);
  out.polygon.resize(total);
  out.next.resize(total);
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t p = which ? (*which)[k] : k;
    const Ring& ring = rings[p];
    const std::int32_t tag = tag_polygons ? static_cast<std::int32_t>(p) : 0;
    const std::uint32_t first = at;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point64 a = ring[i], b = ring[i + 1 == n ? 0 : i + 1];
      if (a == b) continue;
      out.segments[at] = {a, b};
      out.channel[at] = channel;
      out.polygon[at] = tag;
      out.next[at] = at + 1;
      ++at;
    }
    if (at > first) out.next[at - 1] = first;
  }
  out.segments.resize(at);
  out.channel.resize(at);
  out.polygon.resize(at);
  out.next.resize(at);
}

void append_box_edges(const Box64& box, std::uint8_t channel, std::int32_t tag, EdgeList& out) {
  const Point64 corners[4] = {box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}};
  const auto first = static_cast<std::uint32_t>(out.size());
  for (std::uint32_t i = 0; i < 4; ++i) {
    out.segments.push_back({corners[i], corners[(i + 1) % 4]});
    out.channel.push_back(channel);
    out.polygon.push_back(tag);
    out.next.push_back(i + 1 < 4 ? first + i + 1 : first);
  }
}

}  // namespace edgeland::detail
