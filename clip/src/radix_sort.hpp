#pragma once
// Sort by a 64-bit key, LSD radix for large inputs: the plane graph sorts tens of thousands of
// fragment ends per operation, and comparison sorts of them were a third of its time (and still
// a seventh of a 100-square checkerboard's at a few thousand). Bits on which all keys agree are
// skipped (coordinates of one input share their high bits), so typical inputs take three or
// four passes. Digits are 11 bits for large inputs and 8 below 4,096 elements, where counting
// 2,048 buckets per pass would dominate; below 512 a comparison sort wins (measured on point
// keys), and a handful of elements are insertion-sorted. Each pass runs four (8-bit digits) or
// two (11-bit) stretches of the array side by side (lsd_passes): the plane graph's sort of
// 1,500 keys went from 9 to 7 us, and smooth 100,000-vertex graphs a sixth faster.
// Elements with equal keys may come out in any order: both callers' ties are interchangeable
// (equal fragment ends get one vertex id; equal stops of a segment are re-sorted by position
// along it). The order is still a deterministic function of the input. The comparison sort is
// std::sort, a quarter faster here than std::stable_sort and its buffer allocation.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/scratch.hpp"
#include "offsets.hpp"

namespace edgeland::detail {

namespace radix_detail {

// The array is cut into kLanes stretches sorted side by side: each lane counts into its own
// histogram and scatters through its own offsets (lane l's elements of digit d go after those
// of lanes before it, so the sort stays stable). Nearby keys share digits, and one counter
// bumped by consecutive elements is a chain of store-to-load round trips, about five cycles
// each: with lanes interleaved, kLanes chains run at once.
template <int kBits, int kLanes, class T, class KeyOf>
void lsd_passes(std::vector<T>& v, KeyOf& key_of) {
  constexpr std::uint64_t kMask = (std::uint64_t{1} << kBits) - 1;
  constexpr std::size_t kBuckets = std::size_t{1} << kBits;
  const std::uint64_t first = key_of(v[0]);
  std::uint64_t varying = 0;
  for (const T& x : v) varying |= key_of(x) ^ first;
  // The scatter buffer's storage is recycled (scratch.hpp); after an odd number of
  // passes it and v have traded storage, which is as good.
  ScratchVector<T> tmp;
  const std::size_t n = v.size(), lane = n / kLanes;  // the last lane also takes the rest
  std::size_t begin[kLanes + 1];
  for (int l = 0; l < kLanes; ++l) begin[l] = static_cast<std::size_t>(l) * lane;
  begin[kLanes] = n;
  // Each digit starts at the lowest varying bit not yet sorted on: keys made of two 32-bit
  // halves that vary in their low bits only take one pass fewer than with fixed digits.
  for (int shift = 0; shift < 64 && (varying >> shift) != 0; shift += kBits) {
    shift += std::countr_zero(varying >> shift);
    if (tmp.empty()) tmp.resize(n);
    std::array<std::array<std::uint32_t, kBuckets>, kLanes> at{};
    auto digit = [&](const T& x) { return static_cast<std::size_t>((key_of(x) >> shift) & kMask); };
    for (std::size_t i = 0; i < lane; ++i)
      for (int l = 0; l < kLanes; ++l) ++at[l][digit(v[begin[l] + i])];
    for (std::size_t i = begin[kLanes - 1] + lane; i < n; ++i) ++at[kLanes - 1][digit(v[i])];
    // Offsets: digit-major, lane-minor.
    std::uint32_t sum = 0;
    for (std::size_t d = 0; d < kBuckets; ++d)
      for (int l = 0; l < kLanes; ++l) {
        const std::uint32_t c = at[l][d];
        at[l][d] = sum;
        sum += c;
      }
    for (std::size_t i = 0; i < lane; ++i)
      for (int l = 0; l < kLanes; ++l) {
        const T& x = v[begin[l] + i];
        tmp[at[l][digit(x)]++] = x;
      }
    for (std::size_t i = begin[kLanes - 1] + lane; i < n; ++i)
      tmp[at[kLanes - 1][digit(v[i])]++] = v[i];
    v.swap(tmp);
  }
}

}  // namespace radix_detail

// Stable counting sort of v by id_of(x) < buckets, in one pass: for ids that are small next to
// v's size (vertex ids, segment ids), where the radix sort would take two passes or more.
template <class T, class IdOf>
void counting_sort(std::vector<T>& v, std::size_t buckets, IdOf id_of) {
  ScratchVector<std::uint32_t> at;
  at.assign(buckets + 1, 0);
  for (const T& x : v) ++at[id_of(x) + 1];
  add_up_counts(at);
  ScratchVector<T> sorted;
  sorted.resize(v.size());
  for (const T& x : v) sorted[at[id_of(x)]++] = x;
  v.swap(sorted);
}

template <class T, class KeyOf>
void radix_sort(std::vector<T>& v, KeyOf key_of) {
  if (v.size() <= 32) {  // insertion sort: stable, no buffer
    for (std::size_t i = 1; i < v.size(); ++i) {
      T x = v[i];
      const std::uint64_t k = key_of(x);
      std::size_t j = i;
      for (; j > 0 && k < key_of(v[j - 1]); --j) v[j] = v[j - 1];
      v[j] = x;
    }
    return;
  }
  if (v.size() < 512) {  // the buckets' fixed cost would dominate
    std::sort(v.begin(), v.end(), [&](const T& a, const T& b) { return key_of(a) < key_of(b); });
  } else if (v.size() < 4096) {
    radix_detail::lsd_passes<8, 4>(v, key_of);
  } else {
    radix_detail::lsd_passes<11, 2>(v, key_of);
  }
}

}  // namespace edgeland::detail
