#include "point_grid.hpp"

namespace edgeland::detail {

PointGrid::PointGrid(const std::vector<Point64>& points) {
  if (points.empty()) return;
  std::int64_t max_x = points[0].x, max_y = points[0].y;
  min_x_ = points[0].x;
  min_y_ = points[0].y;
  for (const Point64& p : points) {
    min_x_ = std::min(min_x_, p.x);
    min_y_ = std::min(min_y_, p.y);
    max_x = std::max(max_x, p.x);
    max_y = std::max(max_y, p.y);
  }
  // Square cells of about one point each: side ~ sqrt(area / n), never more cells than ~2n.
  const Int128 w = max_x - min_x_ + 1, h = max_y - min_y_ + 1;
  const Int128 n = static_cast<Int128>(points.size());
  std::int64_t side = 1;
  while (Int128(side) * side * n < w * h) side *= 2;
  cell_ = side;
  while (((w + cell_ - 1) / cell_) * ((h + cell_ - 1) / cell_) > 2 * n + 16) cell_ *= 2;
  while ((std::int64_t{1} << shift_) < cell_) ++shift_;
  columns_ = static_cast<std::int64_t>((w + cell_ - 1) / cell_);
  rows_ = static_cast<std::int64_t>((h + cell_ - 1) / cell_);
  cell_begin_.assign(static_cast<std::size_t>(columns_ * rows_) + 1, 0);
  auto cell_of = [&](Point64 p) {
    return static_cast<std::size_t>(column_of(p.x) * rows_ + row_of(p.y));
  };
  for (const Point64& p : points) ++cell_begin_[cell_of(p) + 1];
  for (std::size_t c = 1; c < cell_begin_.size(); ++c) cell_begin_[c] += cell_begin_[c - 1];
  items_.resize(points.size());
  std::vector<std::uint32_t> fill(cell_begin_.begin(), cell_begin_.end() - 1);
  for (std::uint32_t k = 0; k < points.size(); ++k) items_[fill[cell_of(points[k])]++] = k;
}

}  // namespace edgeland::detail
