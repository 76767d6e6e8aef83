#pragma once
// Points bucketed in a uniform grid, for the question snap rounding asks of long segments:
// which points lie within one unit of this segment? Box queries answer it badly when segments
// are long and diagonal (a spike's box covers half the input); here a segment visits only the
// grid cells along it, so the cost is the number of cells it crosses plus the points in them.
// Exact integer arithmetic; the answer is a superset, callers test each point exactly.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "line_floor.hpp"

namespace edgeland::detail {

class PointGrid {
 public:
  // About one point per cell.
  explicit PointGrid(const std::vector<Point64>& points);

  // visit(k) for every points[k] within L-infinity distance 1 of s (and perhaps a few more).
  template <class F>
  void for_each_near(const Segment& s, F&& visit) const;

 private:
  // x >= min_x_ and y >= min_y_ (callers clamp): shifts, as cell_ is a power of two.
  std::int64_t column_of(std::int64_t x) const { return (x - min_x_) >> shift_; }
  std::int64_t row_of(std::int64_t y) const { return (y - min_y_) >> shift_; }
  template <class F>
  void visit_column(std::int64_t c, std::int64_t y_lo, std::int64_t y_hi, F& visit) const;

  std::int64_t min_x_ = 0, min_y_ = 0, cell_ = 1, columns_ = 0, rows_ = 0;
  int shift_ = 0;  // cell_ == 2^shift_
  std::vector<std::uint32_t> cell_begin_;  // CSR: points of cell (c, r) at index c * rows_ + r
  std::vector<std::uint32_t> items_;
};

template <class F>
void PointGrid::visit_column(std::int64_t c, std::int64_t y_lo, std::int64_t y_hi,
                             F& visit) const {
  const std::int64_t r0 = std::max<std::int64_t>(0, row_of(std::max(y_lo, min_y_)));
  const std::int64_t r1 = y_hi < min_y_ ? -1 : std::min(rows_ - 1, row_of(y_hi));
  for (std::int64_t r = r0; r <= r1; ++r) {
    const std::size_t cell = static_cast<std::size_t>(c * rows_ + r);
    for (std::uint32_t i = cell_begin_[cell]; i < cell_begin_[cell + 1]; ++i) visit(items_[i]);
  }
}

template <class F>
void PointGrid::for_each_near(const Segment& s, F&& visit) const {
  if (items_.empty()) return;
  // Walk the columns the segment's x-range (grown by 1) covers; in each, the rows its y-range
  // over that column's x-range (grown by 1, rounded outwards) covers, grown by 1.
  const Point64 a = s.a.x <= s.b.x ? s.a : s.b, b = s.a.x <= s.b.x ? s.b : s.a;
  const std::int64_t x_lo = std::max(a.x - 1, min_x_);
  const std::int64_t x_hi = b.x + 1;
  if (x_hi < min_x_) return;
  const std::int64_t c0 = column_of(x_lo), c1 = std::min(columns_ - 1, column_of(x_hi));
  const Int128 dx = b.x - a.x, dy = b.y - a.y;
  auto y_floor = [&](std::int64_t x) { return line_y_floor(a, dx, dy, x); };
  for (std::int64_t c = c0; c <= c1; ++c) {
    if (dx == 0) {
      visit_column(c, std::min(a.y, b.y) - 1, std::max(a.y, b.y) + 1, visit);
      continue;
    }
    const std::int64_t cx0 = min_x_ + c * cell_, cx1 = cx0 + cell_ - 1;
    const std::int64_t from = std::max(cx0 - 1, a.x), to = std::min(cx1 + 1, b.x);
    if (from > to) continue;
    const std::int64_t y0 = y_floor(from), y1 = y_floor(to);
    visit_column(c, std::min(y0, y1) - 1, std::max(y0, y1) + 2, visit);
  }
}

}  // namespace edgeland::detail
