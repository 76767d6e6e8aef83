#pragma once
// Noding (thesis 3.3): every contact between segments, found exactly.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/recycled_vector.hpp"

namespace edgeland::detail {

struct Contacts {
  // (segment, integer point strictly inside it where it must be split)
  RecycledVector<struct ContactSplitsBuffer, std::pair<std::uint32_t, Point64>> splits;
  // Pixels of proper crossings at non-integer points (rounded by round_to_grid).
  RecycledVector<struct ContactHotBuffer, Point64> hot;
  // Pairs of segments that meet other than at a shared endpoint.
  std::size_t intersections = 0;
  // Only when rings are not known to be simple: two segments of one ring meet other than as
  // ring neighbours at their one shared endpoint (the ring is not strictly simple).
  bool ring_self_contact = false;
};

class SegmentIndex;
class SegmentGrid;

// Finds all contacts among `segments` (candidates from `index`). touched[s] becomes true for
// every segment that meets another one anywhere except ring neighbours (next[s]) at their one
// shared endpoint: an untouched segment shares no point with anything else.
// simple_rings: every ring is strictly simple (validated operands), so two segments of one ring
// meet only as neighbours at their shared endpoint and such pairs are not tested at all.
// Otherwise they are, and c.ring_self_contact records whether any ring meets itself.
// O(r log r + candidate pairs) for r runs of the index.
// When it walks the segments through a SegmentGrid (short runs: spiky inputs) and `grid` is not
// null, the grid is handed out there for snap rounding's point queries.
Contacts find_contacts(const std::vector<Segment>& segments, const std::vector<std::uint32_t>& next,
                       const SegmentIndex& index, bool simple_rings, std::vector<bool>& touched,
                       std::unique_ptr<SegmentGrid>* grid = nullptr);

enum class Meeting : std::uint8_t {
  kNone,            // disjoint
  kSharedEndpoint,  // only a common endpoint of both
  kOther,           // anything else (recorded in the contacts)
};

// Exact classification of one pair, adding what it finds to `c`.
Meeting classify_pair(const Segment& s, std::uint32_t i, const Segment& t, std::uint32_t j,
                      Contacts& c);

// Box of a segment.
Box64 segment_box(const Segment& s);

}  // namespace edgeland::detail
