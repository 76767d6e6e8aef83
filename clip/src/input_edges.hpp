#pragma once
// Edge collection: the operands as one list of directed, tagged integer segments, kept as
// parallel arrays (the later stages each read only some of them).
#include <cstdint>
#include <vector>

#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/scratch.hpp"

namespace edgeland::detail {

// The channel of an edge: which operand it belongs to (the API's Operand), as the small integer
// the stages index their per-operand state by. normalize's rings all go in the subject channel.
inline constexpr std::uint8_t kSubjectChannel = 0, kClipChannel = 1;
constexpr std::uint8_t channel_of(Operand which) {
  return which == Operand::kClip ? kClipChannel : kSubjectChannel;
}

// The arrays are scratch storage (edgeland/kernel/scratch.hpp): an operation's edge list reuses
// the last one's pages. Edge i is segments[i], directed: its left side is the inside of polygon[i]
// of operand channel[i] (for normalize: it adds +1 to the winding number on its left). next[i] is
// the edge that follows it along its ring; the edges of a ring are consecutive.
struct EdgeList {
  ScratchVector<Segment> segments;
  ScratchVector<std::uint8_t> channel;  // kSubjectChannel (also normalize's rings) or kClipChannel
  ScratchVector<std::int32_t> polygon;  // index within its operand
  ScratchVector<std::uint32_t> next;
  // Empty: every edge counts once. Otherwise edge i counts weight[i] times, in its direction
  // (collinear_merge.hpp: merged stretches of many overlapping edges; winding labelings only).
  ScratchVector<std::int32_t> weight;
  std::size_t size() const { return segments.size(); }
  std::int32_t weight_of(std::uint32_t i) const { return weight.empty() ? 1 : weight[i]; }
  void clear() {
    segments.clear();
    channel.clear();
    polygon.clear();
    next.clear();
    weight.clear();
  }
};

// Appends the edges of rings[k] for every k in `which` (all rings when null), tagged with
// polygon k (or 0 when !tag_polygons); zero-length edges (repeated points) are skipped.
void append_ring_edges(const std::vector<Ring>& rings, std::uint8_t channel, bool tag_polygons,
                       EdgeList& out, const std::vector<std::uint32_t>* which = nullptr);

// Appends the counter-clockwise ring of a box of positive area (min, then (max.x, min.y), max,
// (min.x, max.y)) tagged polygon `tag`: a window, without a ring allocated for it.
void append_box_edges(const Box64& box, std::uint8_t channel, std::int32_t tag, EdgeList& out);

}  // namespace edgeland::detail
