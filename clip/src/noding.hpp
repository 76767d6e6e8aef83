#pragma once
// Noding (thesis 3.3): every contact between segments, found exactly.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

struct Contacts {
  // (segment, integer point strictly inside it where it must be split)
  std::vector<std::pair<std::uint32_t, Point64>> splits;
  // Pixels of proper crossings at non-integer points (rounded by round_to_grid).
  std::vector<Point64> hot;
  // Pairs of segments that meet other than at a shared endpoint.
  std::size_t intersections = 0;
};

struct SweepBox;

// Finds all contacts among `segments`, given their boxes sorted_for_sweep (box_sweep.hpp).
// O(n log n + box-overlapping pairs).
Contacts find_contacts(const std::vector<Segment>& segments, const std::vector<SweepBox>& sweep);

// Exact classification of one pair, adding what it finds to `c`.
void classify_pair(const Segment& s, std::uint32_t i, const Segment& t, std::uint32_t j,
                   Contacts& c);

// Box of a segment.
Box64 segment_box(const Segment& s);

}  // namespace edgeland::detail
