#pragma once
// Candidate pairs for exact tests: every pair of boxes that overlap (closed boxes), found by
// sorting on min x and sweeping (the scanbeam of thesis 3.3.2): O(n log n + a) for a the
// number of (box, active box) encounters. Boxes are copied into one contiguous array so the
// sweep touches memory in order; expired boxes leave the active list as it is scanned.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/scratch.hpp"

namespace edgeland::detail {

struct SweepBox {
  std::int64_t min_x, max_x, min_y, max_y;
  std::uint32_t id;
};

// The boxes sorted by min x (then index) into `s`, in place: a caller keeping the array
// (scratch storage) reuses it.
inline void sort_for_sweep(const std::vector<Box64>& boxes, std::vector<SweepBox>& s) {
  s.resize(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i)
    s[i] = {boxes[i].min.x, boxes[i].max.x, boxes[i].min.y, boxes[i].max.y,
            static_cast<std::uint32_t>(i)};
  std::sort(s.begin(), s.end(), [](const SweepBox& a, const SweepBox& b) {
    return a.min_x != b.min_x ? a.min_x < b.min_x : a.id < b.id;
  });
}

inline ScratchVector<SweepBox> sorted_for_sweep(const std::vector<Box64>& boxes) {
  ScratchVector<SweepBox> s;
  sort_for_sweep(boxes, s);
  return s;
}

// The pairs of boxes whose x-ranges overlap (`sorted` by sorted_for_sweep): the sweep's work,
// as each such pair meets once in an active list. Counting stops once past `limit`.
inline std::size_t x_overlapping_pairs(const std::vector<SweepBox>& sorted, std::size_t limit) {
  std::size_t pairs = 0;
  for (auto it = sorted.begin(); it != sorted.end() && pairs <= limit; ++it) {
    const auto end =
        std::upper_bound(it + 1, sorted.end(), it->max_x,
                         [](std::int64_t x, const SweepBox& b) { return x < b.min_x; });
    pairs += static_cast<std::size_t>(end - (it + 1));
  }
  return pairs;
}

// Visits b against the active boxes that still reach it, dropping those that do not.
template <class F>
void sweep_against(std::vector<SweepBox>& active, const SweepBox& b, F&& visit) {
  std::size_t keep = 0;
  for (std::size_t k = 0; k < active.size(); ++k) {
    const SweepBox o = active[k];
    if (o.max_x < b.min_x) continue;
    active[keep++] = o;
    if (o.min_y <= b.max_y && b.min_y <= o.max_y) visit(o.id);
  }
  active.resize(keep);
}

// Calls visit(i, j) once for every i < j whose boxes overlap. Order of calls is unspecified.
template <class F>
void for_each_overlapping_pair(const std::vector<SweepBox>& sorted, F&& visit) {
  ScratchVector<SweepBox> active;
  for (const SweepBox& b : sorted) {
    sweep_against(active, b, [&](std::uint32_t o) { visit(std::min(o, b.id), std::max(o, b.id)); });
    active.push_back(b);
  }
}

template <class F>
void for_each_overlapping_pair(const std::vector<Box64>& boxes, F&& visit) {
  for_each_overlapping_pair(sorted_for_sweep(boxes), visit);
}

// Calls visit(i, j) for every box i of `a` overlapping box j of `b` (both sorted_for_sweep).
template <class F>
void for_each_overlapping_pair(const std::vector<SweepBox>& a, const std::vector<SweepBox>& b,
                               F&& visit) {
  ScratchVector<SweepBox> active_a, active_b;
  std::size_t ia = 0, ib = 0;
  while (ia < a.size() || ib < b.size()) {
    if (ib == b.size() || (ia < a.size() && a[ia].min_x <= b[ib].min_x)) {
      const SweepBox& x = a[ia++];
      sweep_against(active_b, x, [&](std::uint32_t j) { visit(x.id, j); });
      active_a.push_back(x);
    } else {
      const SweepBox& y = b[ib++];
      sweep_against(active_a, y, [&](std::uint32_t i) { visit(i, y.id); });
      active_b.push_back(y);
    }
  }
}

template <class F>
void for_each_overlapping_pair(const std::vector<Box64>& a, const std::vector<Box64>& b,
                               F&& visit) {
  if (a.empty() || b.empty()) return;  // nothing to sort: clip_near often has no left-out box
  for_each_overlapping_pair(sorted_for_sweep(a), sorted_for_sweep(b), visit);
}

}  // namespace edgeland::detail
