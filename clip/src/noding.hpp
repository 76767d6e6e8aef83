#pragma once
// Noding (thesis 3.3): every contact between segments, found exactly.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

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

// Finds all contacts among `segments`. If `involved` is non-empty, only pairs with at least one
// segment marked in it are examined. O(n log n + box-overlapping pairs).
Contacts find_contacts(const std::vector<Segment>& segments,
                       const std::vector<bool>& involved = {});

}  // namespace edgeland::detail
