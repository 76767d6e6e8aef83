#include "validate_event_sort.hpp"

#include <algorithm>
#include <bit>
#include <cstddef>

#include "edgeland/kernel/scratch.hpp"

namespace edgeland::detail {
namespace {

// Below this many events std::sort is cheaper than 2048 counters per radix pass.
constexpr std::size_t kSmall = 256;
// Below this many events, when key and position fit one word, a comparison sort of those
// words beats the radix sort's 4 to 6 passes (measured on a spiky star and a checkerboard:
// about 2x at 400 events, break-even near 4,000).
constexpr std::size_t kPackedMax = 2048;
constexpr unsigned kMaxDigitBits = 11;

// A function object, not a function: std::sort and std::merge then inline the comparison.
constexpr auto key_less = [](const KeyedVertex& a, const KeyedVertex& b) noexcept {
  return a.key < b.key;
};

// Bits needed for the positions 0..n-1 (n >= 1).
unsigned position_bits(std::size_t n) noexcept {
  return static_cast<unsigned>(std::bit_width(n - 1));
}

// Whether each key (< 2^bits) and its position fit one 64-bit word together.
bool packs(std::size_t n, unsigned bits) noexcept { return bits + position_bits(n) <= 64; }

// Sorts by one word per event, its key above its position: the words are distinct and their
// order is the stable order, so std::sort moves and compares plain integers, half the size
// of an event, with no tie-break. The events are then gathered in that order.
void sort_packed(std::vector<KeyedVertex>& events, std::vector<KeyedVertex>& scratch) {
  ScratchVector<std::uint64_t> words;
  const unsigned shift = position_bits(events.size());
  const std::uint64_t position_mask = (std::uint64_t{1} << shift) - 1;
  words.resize(events.size());
  for (std::size_t k = 0; k < events.size(); ++k) words[k] = events[k].key << shift | k;
  std::sort(words.begin(), words.end());
  scratch.resize(events.size());
  for (std::size_t k = 0; k < words.size(); ++k) scratch[k] = events[words[k] & position_mask];
  events.swap(scratch);
}

// LSD radix sort (stable): one counting read and one scatter per digit.
void radix_sort(std::vector<KeyedVertex>& events, std::vector<KeyedVertex>& scratch,
                unsigned bits) {
  if (bits == 0) return;
  const unsigned passes = (bits + kMaxDigitBits - 1) / kMaxDigitBits;
  const unsigned width = (bits + passes - 1) / passes;
  const std::uint64_t mask = (std::uint64_t{1} << width) - 1;
  std::vector<std::uint32_t> count(std::size_t{1} << width);
  scratch.resize(events.size());
  for (unsigned pass = 0, shift = 0; pass < passes; ++pass, shift += width) {
    std::fill(count.begin(), count.end(), 0);
    for (const KeyedVertex& e : events) ++count[(e.key >> shift) & mask];
    std::uint32_t sum = 0;
    for (std::uint32_t& c : count) {
      const std::uint32_t here = c;
      c = sum;
      sum += here;
    }
    for (const KeyedVertex& e : events) scratch[count[(e.key >> shift) & mask]++] = e;
    events.swap(scratch);
  }
}

// Cuts `events` into maximal ascending runs, reversing each strictly descending stretch, and
// returns the run bounds (0, ..., n); stops early, with a partial answer, past `limit` runs.
std::vector<std::uint32_t> monotone_runs(std::vector<KeyedVertex>& events, std::size_t limit) {
  std::vector<std::uint32_t> bounds{0};
  const std::size_t n = events.size();
  std::size_t start = 0;
  while (start < n && bounds.size() <= limit) {
    std::size_t end = start + 1;
    if (end < n && events[end].key < events[start].key) {
      while (end < n && events[end].key < events[end - 1].key) ++end;
      std::reverse(events.begin() + static_cast<std::ptrdiff_t>(start),
                   events.begin() + static_cast<std::ptrdiff_t>(end));
    } else {
      while (end < n && events[end].key >= events[end - 1].key) ++end;
    }
    bounds.push_back(static_cast<std::uint32_t>(end));
    start = end;
  }
  return bounds;
}

// Merges neighbouring runs pairwise until one is left (stable).
void merge_runs(std::vector<KeyedVertex>& events, std::vector<KeyedVertex>& scratch,
                std::vector<std::uint32_t> bounds) {
  scratch.resize(events.size());
  std::vector<std::uint32_t> next;
  while (bounds.size() > 2) {
    next.assign(1, 0);
    for (std::size_t r = 0; r + 1 < bounds.size(); r += 2) {
      const std::uint32_t lo = bounds[r], mid = bounds[r + 1];
      const std::uint32_t hi = r + 2 < bounds.size() ? bounds[r + 2] : mid;
      std::merge(events.begin() + lo, events.begin() + mid, events.begin() + mid,
                 events.begin() + hi, scratch.begin() + lo, key_less);
      next.push_back(hi);
    }
    events.swap(scratch);
    bounds.swap(next);
  }
}

}  // namespace

void sort_by_key(std::vector<KeyedVertex>& events, std::vector<KeyedVertex>& scratch,
                 unsigned bits) {
  if (events.size() < kSmall) {
    std::sort(events.begin(), events.end(), [](const KeyedVertex& a, const KeyedVertex& b) {
      return a.key < b.key || (a.key == b.key && a.vertex < b.vertex);
    });
    return;
  }
  // A merge pass costs about half a radix pass (no counting): merge while log2(runs) is at
  // most twice the radix passes.
  const unsigned radix_passes = (bits + kMaxDigitBits - 1) / kMaxDigitBits;
  const std::size_t most_runs = std::size_t{1} << std::min(2 * radix_passes, 30u);
  std::vector<std::uint32_t> bounds = monotone_runs(events, most_runs);
  if (bounds.back() == events.size() && bounds.size() - 1 <= most_runs) {
    merge_runs(events, scratch, std::move(bounds));
  } else if (events.size() <= kPackedMax && packs(events.size(), bits)) {
    // The runs found so far were reversed only where strictly descending, which keeps equal
    // keys in their order: positions now are as good a tie-break as before.
    sort_packed(events, scratch);
  } else {
    radix_sort(events, scratch, bits);
  }
}

}  // namespace edgeland::detail
