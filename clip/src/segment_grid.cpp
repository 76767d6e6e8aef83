#include "segment_grid.hpp"

#include "edgeland/kernel/grid_cells.hpp"
#include "offsets.hpp"

namespace edgeland::detail {

void SegmentGrid::set_side(std::int64_t side) {
  side_ = side;
  shift_ = 0;
  while ((std::int64_t{1} << shift_) < side_) ++shift_;
  columns_ = ((max_x_ - min_x_) >> shift_) + 1;
  rows_ = ((max_y_ - min_y_) >> shift_) + 1;
}

namespace {

constexpr std::size_t kRegistrationsPerSegment = 32;

// About how many cells the walks of for_each_cell register the segments in, for cells of the
// given side: a segment spans about |dx| / side columns and |dy| / side rows, and the walk
// visits about their sum.
std::size_t registrations(const std::vector<Segment>& segments, std::int64_t side) {
  std::size_t total = 0;
  for (const Segment& s : segments) {
    const auto dx = static_cast<std::uint64_t>(s.a.x < s.b.x ? s.b.x - s.a.x : s.a.x - s.b.x);
    const auto dy = static_cast<std::uint64_t>(s.a.y < s.b.y ? s.b.y - s.a.y : s.a.y - s.b.y);
    total += static_cast<std::size_t>(dx / static_cast<std::uint64_t>(side) +
                                      dy / static_cast<std::uint64_t>(side)) +
             2;
  }
  return total;
}

}  // namespace

SegmentGrid::SegmentGrid(const std::vector<Segment>& segments) {
  const std::size_t n = segments.size();
  if (n == 0) return;
  min_x_ = max_x_ = segments[0].a.x;
  min_y_ = max_y_ = segments[0].a.y;
  for (const Segment& s : segments)
    for (Point64 p : {s.a, s.b}) {
      min_x_ = std::min(min_x_, p.x);
      max_x_ = std::max(max_x_, p.x);
      min_y_ = std::min(min_y_, p.y);
      max_y_ = std::max(max_y_, p.y);
    }
  const Box64 extent{{min_x_, min_y_}, {max_x_, max_y_}};
  const std::uint64_t cell_limit = 4 * std::uint64_t{n} + 16;
  // One to four cells per segment (a power-of-two side). The work is registrations plus pairs
  // tested inside cells; on spiky stars, their fragments and checkerboards this size came within
  // 15% of the best of half and twice the side.
  std::int64_t side = 1;
  while (cells_area(side, n) < point_count(extent)) side *= 2;
  if (side > 1) side /= 2;
  while (cells_covering(extent, side) > cell_limit) side *= 2;
  // Long segments cross many cells: a stack of 10^4 edges 10^5 long over a thin box took 10^8
  // registrations (1.5 GB) at the side above. Keep them within a few dozen per segment on
  // average (spiky stars of 4 * 10^5 segments ran as fast at 32 as with no bound, in two thirds
  // of the memory; 8 doubled their time).
  while (registrations(segments, side) > kRegistrationsPerSegment * n + 1024) side *= 2;

  set_side(side);
  // One walk records every (cell, segment) registration in segment order; a counting sort by
  // cell then lists each cell's segments in increasing id order.
  ScratchVector<std::uint32_t> entry_cells;
  entry_cells.reserve(4 * n);
  slot_begin_.assign(n + 1, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    for_each_cell(segments[i],
                  [&](std::size_t k) { entry_cells.push_back(static_cast<std::uint32_t>(k)); });
    slot_begin_[i + 1] = static_cast<std::uint32_t>(entry_cells.size());
  }
  cell_begin_.assign(static_cast<std::size_t>(columns_ * rows_) + 1, 0);
  for (std::uint32_t k : entry_cells) ++cell_begin_[k + 1];
  add_up_counts(cell_begin_);
  items_.resize(entry_cells.size());
  slots_.resize(entry_cells.size());
  ScratchVector<std::uint32_t> fill;
  fill.assign(cell_begin_.begin(), cell_begin_.end() - 1);
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t e = slot_begin_[i]; e < slot_begin_[i + 1]; ++e) {
      const std::uint32_t k = entry_cells[e];
      slots_[e] = {fill[k], cell_begin_[k + 1]};
      items_[fill[k]++] = i;
    }
}

}  // namespace edgeland::detail

namespace edgeland::detail {

std::size_t SegmentGrid::cell_pairs() const {
  std::size_t pairs = 0;
  for (std::size_t k = 0; k + 1 < cell_begin_.size(); ++k) {
    const std::size_t in_cell = cell_begin_[k + 1] - cell_begin_[k];
    pairs += in_cell * (in_cell - 1) / 2;
  }
  return pairs;
}

}  // namespace edgeland::detail
