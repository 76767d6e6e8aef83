#pragma once
// Overlapping pairs of many short boxes spread over the plane (the fragments of spiky inputs,
// after snap rounding has cut them at every crossing): a uniform grid, each box in the cells it
// covers, each overlapping pair reported once, by the cell that holds the lower-left corner of
// the two boxes' intersection (both boxes cover that cell). A sweep over x would compare every
// box with all boxes spanning its x, which for long spiky inputs is most of them.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "box_sweep.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/grid_cells.hpp"
#include "edgeland/kernel/int128.hpp"
#include "offsets.hpp"

namespace edgeland::detail {

// The grid's cells: squares of side `cell` from the lower-left corner of all boxes, numbered
// column by column.
struct BoxGridCells {
  Box64 all;
  std::int64_t cell = 1;
  std::int64_t rows = 0;
  std::size_t cells = 0;

  std::int64_t column(std::int64_t x) const { return (x - all.min.x) / cell; }
  std::int64_t row(std::int64_t y) const { return (y - all.min.y) / cell; }
  // f(k) for every cell k that box b covers.
  template <class F>
  void for_cells(const Box64& b, F&& f) const {
    for (std::int64_t c = column(b.min.x); c <= column(b.max.x); ++c)
      for (std::int64_t r = row(b.min.y); r <= row(b.max.y); ++r)
        f(static_cast<std::size_t>(c * rows + r));
  }
  // How many (box, cell) entries the boxes make.
  Int128 entries(const std::vector<Box64>& boxes) const {
    Int128 sum = 0;
    for (const Box64& b : boxes)
      sum += block_size(column(b.max.x) - column(b.min.x) + 1, row(b.max.y) - row(b.min.y) + 1);
    return sum;
  }
};

// Cells about as large as a typical box (n >= 1 boxes), and never many more cells than boxes.
inline BoxGridCells size_box_grid(const std::vector<Box64>& boxes) {
  const std::size_t n = boxes.size();
  BoxGridCells g;
  g.all = boxes[0];
  Int128 extent = 0;
  for (const Box64& b : boxes) {
    g.all.expand(b);
    extent += std::max(b.max.x - b.min.x, b.max.y - b.min.y);
  }
  g.cell = std::max<std::int64_t>(1, static_cast<std::int64_t>(extent / n));
  while (cells_covering(g.all, g.cell) > 4 * std::uint64_t{n} + 16) g.cell *= 2;
  g.rows = g.row(g.all.max.y) + 1;
  g.cells = static_cast<std::size_t>(g.column(g.all.max.x) + 1) * static_cast<std::size_t>(g.rows);
  return g;
}

// visit(i, j), i < j, for every overlapping pair of boxes that share cell k of the lists
// (items[begin[k]..begin[k + 1]) are its boxes), once: by the cell that holds the lower-left
// corner of the two boxes' intersection.
template <class F>
void visit_pairs_by_cell(const std::vector<Box64>& boxes, const BoxGridCells& g,
                         const std::vector<std::uint32_t>& begin,
                         const std::vector<std::uint32_t>& items, F&& visit) {
  for (std::size_t k = 0; k < g.cells; ++k) {
    const std::int64_t c = static_cast<std::int64_t>(k) / g.rows,
                       r = static_cast<std::int64_t>(k) % g.rows;
    for (std::uint32_t x = begin[k]; x < begin[k + 1]; ++x) {
      const Box64& bi = boxes[items[x]];
      for (std::uint32_t y = x + 1; y < begin[k + 1]; ++y) {
        const Box64& bj = boxes[items[y]];
        if (!bi.overlaps(bj)) continue;
        if (g.column(std::max(bi.min.x, bj.min.x)) != c || g.row(std::max(bi.min.y, bj.min.y)) != r)
          continue;  // reported by the cell of the intersection's lower-left corner
        visit(std::min(items[x], items[y]), std::max(items[x], items[y]));
      }
    }
  }
}

// Calls visit(i, j), i < j, once for every pair of closed boxes that overlap. Falls back to the
// sweep of box_sweep.hpp when the boxes are too uneven for a grid.
template <class F>
void for_each_overlapping_pair_in_grid(const std::vector<Box64>& boxes, F&& visit) {
  const std::size_t n = boxes.size();
  if (n < 2) return;
  const BoxGridCells g = size_box_grid(boxes);
  // A few huge boxes among many small ones would fill every cell: past 32 cells per box on
  // average, the sweep is the better tool.
  if (g.entries(boxes) > 32 * std::uint64_t{n}) {
    for_each_overlapping_pair(sorted_for_sweep(boxes), visit);
    return;
  }
  ScratchVector<std::uint32_t> begin;
  begin.assign(g.cells + 1, 0);
  for (const Box64& b : boxes) g.for_cells(b, [&](std::size_t k) { ++begin[k + 1]; });
  // Cells sized for the typical box's longer side can hold thousands of thin ones (the teeth of
  // a comb 10^8 long and 40 wide: one cell, all pairs). When the cells' pairs are many, count
  // the sweep's and take the cheaper.
  std::size_t cell_pairs = 0;
  for (std::size_t k = 1; k <= g.cells; ++k)
    cell_pairs += std::size_t{begin[k]} * (begin[k] - 1) / 2;
  if (cell_pairs > 8 * n + 1024) {
    const ScratchVector<SweepBox> sorted = sorted_for_sweep(boxes);
    if (x_overlapping_pairs(sorted, cell_pairs) < cell_pairs) {
      for_each_overlapping_pair(sorted, visit);
      return;
    }
  }
  add_up_counts(begin);
  ScratchVector<std::uint32_t> items, fill;
  items.resize(begin[g.cells]);
  fill.assign(begin.begin(), begin.end() - 1);
  for (std::uint32_t i = 0; i < n; ++i)
    g.for_cells(boxes[i], [&](std::size_t k) { items[fill[k]++] = i; });
  visit_pairs_by_cell(boxes, g, begin, items, visit);
}

}  // namespace edgeland::detail
