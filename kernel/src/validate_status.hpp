#pragma once
// Private to validate_accept_sweep.cpp: the sweep status, a sequence of edge numbers bottom-up.
//
// Usually only a few edges are cut by the sweep line, and a flat array is the cheapest
// status there is. But a spiky ring can keep 10^4 edges in it, and a flat array would then
// move half of them at every insert. So once it first holds more than 2 kBlock entries the
// sequence is kept in blocks of at most 2 kBlock entries: an insert or erase then moves at
// most one block and renumbers the block starts, O(kBlock + size / kBlock); a look-up by
// index or by predicate costs O(log size) either way.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/scratch.hpp"

namespace edgeland::detail {

class SweepStatus {
 public:
  std::size_t size() const noexcept { return blocks_.empty() ? flat_.size() : starts_.back(); }
  bool empty() const noexcept { return size() == 0; }

  std::uint32_t operator[](std::size_t i) const noexcept {
    if (blocks_.empty()) return flat_[i];
    const Place p = locate(i);
    return blocks_[p.block][p.offset];
  }
  void set(std::size_t i, std::uint32_t value) noexcept {
    if (blocks_.empty()) {
      flat_[i] = value;
      return;
    }
    const Place p = locate(i);
    blocks_[p.block][p.offset] = value;
  }

  // The first index whose entry e has !below(e), for a `below` true on a prefix.
  template <class Below>
  [[gnu::always_inline]] std::size_t partition_point(Below below) const {
    if (blocks_.empty()) return first_not(flat_, below);
    std::size_t lo = 0, hi = blocks_.size();
    while (lo < hi) {  // the first block whose last entry is not below
      const std::size_t mid = (lo + hi) / 2;
      if (!blocks_[mid].empty() && below(blocks_[mid].back())) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    if (lo == blocks_.size()) return size();
    return starts_[lo] + first_not(blocks_[lo], below);
  }

  // Replaces the `count` entries from index i by values[0, k).
  void replace(std::size_t i, std::size_t count, const std::uint32_t* values, std::size_t k) {
    if (blocks_.empty()) {
      replace_flat(i, count, values, k);
      if (flat_.size() > 2 * kBlock) to_blocks();
      return;
    }
    const std::size_t same = std::min(count, k);
    for (std::size_t m = 0; m < same; ++m) set(i + m, values[m]);
    if (count > k) erase(i + k, count - k);
    if (k > count) insert(i + count, values + count, k - count);
  }

 private:
  static constexpr std::size_t kBlock = 512;

  struct Place {
    std::size_t block;
    std::size_t offset;
  };

  template <class Below>
  [[gnu::always_inline]] static std::size_t first_not(const std::vector<std::uint32_t>& v,
                                                      Below below) {
    std::size_t lo = 0, hi = v.size();
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (below(v[mid])) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    return lo;
  }

  // replace() on the flat array. Element by element: an event moves a few entries, and a
  // library call for each move (vector insert and erase) cost more than the moving.
  void replace_flat(std::size_t i, std::size_t count, const std::uint32_t* values, std::size_t k) {
    const std::size_t old_size = flat_.size();
    if (k > count) flat_.resize(old_size + (k - count));
    std::uint32_t* const v = flat_.data();
    if (k > count) {  // the tail moves up, from its top
      for (std::size_t m = old_size; m-- > i + count;) v[m + (k - count)] = v[m];
    } else if (k < count) {  // the tail moves down, from its bottom
      for (std::size_t m = i + count; m < old_size; ++m) v[m - (count - k)] = v[m];
    }
    for (std::size_t m = 0; m < k; ++m) v[i + m] = values[m];
    if (k < count) flat_.resize(old_size - (count - k));
  }

  // The flat array has grown too long: cut it into blocks of kBlock entries.
  void to_blocks() {
    for (std::size_t at = 0; at < flat_.size(); at += kBlock) {
      const auto from = flat_.begin() + static_cast<std::ptrdiff_t>(at);
      blocks_.emplace_back(from,
                           from + static_cast<std::ptrdiff_t>(std::min(kBlock, flat_.size() - at)));
    }
    flat_.clear();
    renumber();
  }

  // Where index i (<= size) lives; the end is just past the last entry of the last block.
  Place locate(std::size_t i) const noexcept {
    const auto after = std::upper_bound(starts_.begin() + 1, starts_.end() - 1, i);
    const auto b = static_cast<std::size_t>(after - starts_.begin()) - 1;
    return {b, i - starts_[b]};
  }

  void insert(std::size_t i, const std::uint32_t* values, std::size_t k) {
    const Place p = locate(i);
    std::vector<std::uint32_t>& b = blocks_[p.block];
    b.insert(b.begin() + static_cast<std::ptrdiff_t>(p.offset), values, values + k);
    if (b.size() > 2 * kBlock) {  // split in halves
      std::vector<std::uint32_t> upper(b.begin() + static_cast<std::ptrdiff_t>(b.size() / 2),
                                       b.end());
      b.resize(b.size() / 2);
      blocks_.insert(blocks_.begin() + static_cast<std::ptrdiff_t>(p.block) + 1, std::move(upper));
    }
    renumber();
  }

  void erase(std::size_t i, std::size_t count) {
    while (count > 0) {
      const Place p = locate(i);
      std::vector<std::uint32_t>& b = blocks_[p.block];
      const std::size_t m = std::min(count, b.size() - p.offset);
      b.erase(b.begin() + static_cast<std::ptrdiff_t>(p.offset),
              b.begin() + static_cast<std::ptrdiff_t>(p.offset + m));
      count -= m;
      // The block joins a neighbour when both fit one block, so any two neighbouring blocks
      // hold more than kBlock entries and there are at most 2 size / kBlock + 1 blocks.
      // (An empty block goes, unless it is the only one.)
      if (b.empty() && blocks_.size() > 1) {
        blocks_.erase(blocks_.begin() + static_cast<std::ptrdiff_t>(p.block));
      } else {
        merge_if_small(p.block);
      }
      if (p.block > 0) merge_if_small(p.block - 1);
      renumber();
    }
  }

  // Moves block b + 1 into block b if they fit one block together.
  void merge_if_small(std::size_t b) {
    if (b + 1 >= blocks_.size() || blocks_[b].size() + blocks_[b + 1].size() > kBlock) return;
    blocks_[b].insert(blocks_[b].end(), blocks_[b + 1].begin(), blocks_[b + 1].end());
    blocks_.erase(blocks_.begin() + static_cast<std::ptrdiff_t>(b) + 1);
  }

  void renumber() {
    starts_.resize(blocks_.size() + 1);
    for (std::size_t b = 0; b < blocks_.size(); ++b)
      starts_[b + 1] = starts_[b] + blocks_[b].size();
  }

  ScratchVector<std::uint32_t> flat_;               // the status while it is short
  std::vector<std::vector<std::uint32_t>> blocks_;  // then: none empty unless alone
  std::vector<std::size_t> starts_;  // index of each block's first entry, then size()
};

}  // namespace edgeland::detail
