#pragma once
// Private to validate_*.cpp: sorting the sweep's events, each a vertex with one 64-bit key
// whose unsigned order is the sweep order.
#include <cstdint>
#include <vector>

namespace edgeland::detail {

struct KeyedVertex {
  std::uint64_t key;
  std::uint32_t vertex;
};

// Sorts `events` by key; equal keys end up in an order that depends only on the input. Every
// key is below 2^bits; `scratch` is working memory.
//
// Events listed in ring order are mostly sorted already: a ring is a few monotone chains. So
// the maximal monotone runs are found first (descending ones reversed), and if they are few
// they are merged pairwise, log2(runs) passes; otherwise an LSD radix sort does as many
// passes of at most 11 bits as the keys have bits. Either way O(n) passes of O(1) words:
// O(n log runs) or O(n bits / 11).
void sort_by_key(std::vector<KeyedVertex>& events, std::vector<KeyedVertex>& scratch,
                 unsigned bits);

}  // namespace edgeland::detail
