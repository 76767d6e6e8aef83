#pragma once
// Private to validate_*.cpp: sorting the sweep's events, each a vertex with one 64-bit key
// whose unsigned order is the sweep order.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/point.hpp"

namespace edgeland::detail {

struct KeyedVertex {
  std::uint64_t key;
  std::uint32_t vertex;
};

// Bits needed for offsets 0..span of one coordinate (span >= 0).
inline unsigned sweep_key_bits(std::int64_t span) noexcept {
  return static_cast<unsigned>(std::bit_width(static_cast<std::uint64_t>(span)));
}

// A point of the box from `low` as one key whose unsigned order is the sweep order: its
// offsets from the box's lower-left corner, x above y, y taking y_bits bits.
inline std::uint64_t sweep_key(Point64 p, Point64 low, unsigned y_bits) noexcept {
  return (static_cast<std::uint64_t>(p.x - low.x) << y_bits) |
         static_cast<std::uint64_t>(p.y - low.y);
}

// Sorts `events` by key, stably (equal keys keep their order). Every key is below 2^bits;
// `scratch` is working memory.
//
// Events listed in ring order are mostly sorted already: a ring is a few monotone chains. So
// the maximal monotone runs are found first (descending ones reversed), and if they are few
// they are merged pairwise, log2(runs) passes; otherwise an LSD radix sort does as many
// passes of at most 11 bits as the keys have bits. Either way O(n) passes of O(1) words:
// O(n log runs) or O(n bits / 11). Up to a few thousand events whose key and position fit
// one 64-bit word, std::sort of those words is cheaper than either (O(n log n) with n
// bounded by a constant, so the bound above stands).
void sort_by_key(std::vector<KeyedVertex>& events, std::vector<KeyedVertex>& scratch,
                 unsigned bits);

// The indices 0..n-1 (in `vertex`) ordered by the in-range points point_of(i) in sweep order
// (x, then y), equal points by index. n < 2^32. O(n) besides sort_by_key.
template <class PointOf>
std::vector<KeyedVertex> sorted_by_point(std::size_t n, PointOf point_of) {
  std::vector<KeyedVertex> events(n), scratch;
  if (n == 0) return events;
  Box64 box{point_of(0), point_of(0)};
  for (std::size_t i = 1; i < n; ++i) box.expand(point_of(i));
  const unsigned y_bits = sweep_key_bits(box.max.y - box.min.y);
  for (std::size_t i = 0; i < n; ++i) {
    events[i] = {sweep_key(point_of(i), box.min, y_bits), static_cast<std::uint32_t>(i)};
  }
  sort_by_key(events, scratch, y_bits + sweep_key_bits(box.max.x - box.min.x));
  return events;
}

}  // namespace edgeland::detail
