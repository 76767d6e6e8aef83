#include "box_sweep.hpp"

#include <algorithm>
#include <numeric>

namespace edgeland::detail {
namespace {

std::vector<std::uint32_t> order_by_min_x(const std::vector<Box64>& boxes) {
  std::vector<std::uint32_t> order(boxes.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) {
    if (boxes[i].min.x != boxes[j].min.x) return boxes[i].min.x < boxes[j].min.x;
    return i < j;
  });
  return order;
}

bool y_overlap(const Box64& a, const Box64& b) {
  return a.min.y <= b.max.y && b.min.y <= a.max.y;
}

// Active list: boxes whose x-range still reaches the sweep position. Expired boxes are
// dropped lazily when the list is scanned.
void prune(std::vector<std::uint32_t>& active, const std::vector<Box64>& boxes, std::int64_t x) {
  std::size_t keep = 0;
  for (std::uint32_t k : active)
    if (boxes[k].max.x >= x) active[keep++] = k;
  active.resize(keep);
}

}  // namespace

void for_each_overlapping_pair(const std::vector<Box64>& boxes,
                               const std::function<void(std::uint32_t, std::uint32_t)>& visit) {
  const auto order = order_by_min_x(boxes);
  std::vector<std::uint32_t> active;
  std::int64_t pruned_at = INT64_MIN;
  for (std::uint32_t i : order) {
    const Box64& b = boxes[i];
    if (active.size() > 32 && b.min.x != pruned_at) {
      prune(active, boxes, b.min.x);
      pruned_at = b.min.x;
    }
    for (std::uint32_t k : active) {
      const Box64& o = boxes[k];
      if (o.max.x >= b.min.x && y_overlap(o, b)) visit(std::min(i, k), std::max(i, k));
    }
    active.push_back(i);
  }
}

void for_each_overlapping_pair(const std::vector<Box64>& a, const std::vector<Box64>& b,
                               const std::function<void(std::uint32_t, std::uint32_t)>& visit) {
  const auto oa = order_by_min_x(a);
  const auto ob = order_by_min_x(b);
  std::vector<std::uint32_t> active_a, active_b;
  std::size_t ia = 0, ib = 0;
  // Merge the two sorted streams; each new box is tested against the other side's active list.
  while (ia < oa.size() || ib < ob.size()) {
    const bool take_a =
        ib == ob.size() || (ia < oa.size() && a[oa[ia]].min.x <= b[ob[ib]].min.x);
    if (take_a) {
      const std::uint32_t i = oa[ia++];
      const Box64& bx = a[i];
      if (active_b.size() > 32) prune(active_b, b, bx.min.x);
      for (std::uint32_t k : active_b)
        if (b[k].max.x >= bx.min.x && y_overlap(b[k], bx)) visit(i, k);
      active_a.push_back(i);
    } else {
      const std::uint32_t j = ob[ib++];
      const Box64& bx = b[j];
      if (active_a.size() > 32) prune(active_a, a, bx.min.x);
      for (std::uint32_t k : active_a)
        if (a[k].max.x >= bx.min.x && y_overlap(a[k], bx)) visit(k, j);
      active_b.push_back(j);
    }
  }
}

}  // namespace edgeland::detail
