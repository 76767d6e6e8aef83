#include "assembly.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "edgeland/kernel/area.hpp"

namespace edgeland::detail {

std::vector<std::vector<std::uint32_t>> split_at_repeated_vertices(
    const PlaneGraph& g, const std::vector<std::uint32_t>& walk,
    std::vector<std::int32_t>& position) {
  std::vector<std::vector<std::uint32_t>> loops;
  std::vector<std::uint32_t> stack;  // half-edges; position[v]: index of the one leaving v
  for (std::uint32_t h : walk) {
    const std::uint32_t v = g.origin(h);
    if (position[v] >= 0) {
      // v closes a loop: every half-edge pushed since v was first left.
      const std::size_t start = static_cast<std::size_t>(position[v]);
      loops.emplace_back(stack.begin() + static_cast<std::ptrdiff_t>(start), stack.end());
      for (std::size_t i = start; i < stack.size(); ++i) position[g.origin(stack[i])] = -1;
      stack.resize(start);
    }
    position[v] = static_cast<std::int32_t>(stack.size());
    stack.push_back(h);
  }
  for (std::uint32_t h : stack) position[g.origin(h)] = -1;
  if (!stack.empty()) loops.push_back(std::move(stack));
  return loops;
}

std::vector<std::pair<FaceLabel, std::vector<std::uint32_t>>> trace_boundaries(
    const PlaneGraph& g, const std::vector<FaceLabel>& emitted) {
  const std::size_t nh = emitted.size();
  std::vector<std::pair<FaceLabel, std::vector<std::uint32_t>>> walks;
  std::vector<bool> used(nh, false);
  for (std::uint32_t start = 0; start < nh; ++start) {
    const FaceLabel label = emitted[start];
    if (label < 0 || used[start]) continue;
    std::vector<std::uint32_t> walk;
    std::uint32_t cur = start;
    do {
      used[cur] = true;
      walk.push_back(cur);
      // Sharpest left turn: from the reversed edge, turn clockwise to the first edge that
      // bounds the same region.
      const std::uint32_t w = g.target(cur), b = g.around_begin[w];
      const std::uint32_t n = g.around_begin[w + 1] - b;
      const std::uint32_t k = g.position_of[cur ^ 1] - b;
      std::uint32_t next = cur;
      for (std::uint32_t i = 1, at = k; i <= n; ++i) {
        at = at == 0 ? n - 1 : at - 1;  // clockwise, wrapping without a division
        const std::uint32_t h = g.around[b + at];
        if (emitted[h] == label) {
          next = h;
          break;
        }
      }
      if (next == cur || (used[next] && next != start))
        throw std::logic_error("assembly: region boundary does not close");
      cur = next;
    } while (cur != start);
    walks.emplace_back(label, std::move(walk));
  }
  return walks;
}

std::vector<RegionRings> assemble(const PlaneGraph& g, const std::vector<SideState>& left,
                                  const LabelOf& label_of) {
  std::vector<FaceLabel> emitted(2 * g.edge_count(), -1);
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const FaceLabel l = label_of(left[2 * e]), r = label_of(left[2 * e + 1]);
    if (l == r) continue;
    emitted[2 * e] = l;
    emitted[2 * e + 1] = r;
  }
  std::map<FaceLabel, RegionRings> regions;
  std::vector<std::int32_t> position(g.vertices.size(), -1);
  for (const auto& [label, walk] : trace_boundaries(g, emitted)) {
    RegionRings& region = regions[label];
    region.label = label;
    for (const auto& loop : split_at_repeated_vertices(g, walk, position)) {
      Ring ring;
      for (std::uint32_t h : loop) g.append_points(h, ring);
      if (ring.size() < 3) continue;
      const Int128 area = twice_signed_area(ring);
      if (area > 0) region.outers.push_back(std::move(ring));
      else if (area < 0) region.holes.push_back(std::move(ring));
    }
  }
  std::vector<RegionRings> out;
  out.reserve(regions.size());
  for (auto& [label, region] : regions) out.push_back(std::move(region));
  return out;
}

}  // namespace edgeland::detail
