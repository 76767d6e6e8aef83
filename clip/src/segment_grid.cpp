#include "segment_grid.hpp"

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <utility>

#include "edgeland/kernel/assert.hpp"
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

Box64 bounding_box(const std::vector<Segment>& segments) {
  Box64 b{segments[0].a, segments[0].a};
  for (const Segment& s : segments) {
    b.expand(s.a);
    b.expand(s.b);
  }
  return b;
}

}  // namespace

SegmentGrid::SegmentGrid(const std::vector<Segment>& segments)
    : SegmentGrid(segments, segments.empty() ? Box64{} : bounding_box(segments)) {}

SegmentGrid::SegmentGrid(const std::vector<Segment>& segments, const Box64& extent) {
  const std::size_t n = segments.size();
  if (n == 0) return;
  min_x_ = extent.min.x;
  min_y_ = extent.min.y;
  max_x_ = extent.max.x;
  max_y_ = extent.max.y;
  EDGELAND_ASSERT(extent.contains(bounding_box(segments)), "segment grid",
                  "a segment outside the extent");
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
  // A cell's offsets span at most (|n.x| + |n.y|) * side <= 2^11 * side: 2^5 steps per side
  // keep them below 2^16.
  offset_shift_ = std::max(0, shift_ - 5);
  // One walk records every (cell, segment) registration in segment order, straight into the
  // slots, reserved at their exact number (growing a list of 10^7 registrations by doubling
  // copied it and held both copies: at zigzag stars of 10^6 the kernel's zeroing of fresh pages
  // was a fifth of the time); the cells' sizes follow from them.
  std::size_t walked = 0;
  for (const Segment& s : segments) walked += cells_walked(s);
  slot_cell_.reserve(walked);
  slot_begin_.assign(n + 1, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    for_each_cell(segments[i],
                  [&](std::size_t k) { slot_cell_.push_back(static_cast<std::uint32_t>(k)); });
    slot_begin_[i + 1] = static_cast<std::uint32_t>(slot_cell_.size());
  }
  registrations_ = slot_cell_.size();
  cell_begin_.assign(static_cast<std::size_t>(columns_ * rows_) + 1, 0);
  for (std::uint32_t k : slot_cell_) ++cell_begin_[k + 1];
  add_up_counts(cell_begin_);
}

void SegmentGrid::fill_lists() {
  if (!items_.empty() || registrations_ == 0) return;
  // A counting sort by cell: each cell lists its segments in increasing id order, and each slot
  // learns its place (unless the pair walks are over: then only the lists are wanted).
  items_.resize(registrations_);
  if (!pair_walks_done_) slot_at_.resize(registrations_);
  ScratchVector<std::uint32_t> fill;
  fill.assign(cell_begin_.begin(), cell_begin_.end() - 1);
  for (std::uint32_t i = 0; i + 1 < slot_begin_.size(); ++i)
    for (std::uint32_t e = slot_begin_[i]; e < slot_begin_[i + 1]; ++e) {
      const std::uint32_t at = fill[slot_cell_[e]]++;
      if (!pair_walks_done_) slot_at_[e] = at;
      items_[at] = i;
    }
  if (pair_walks_done_) drop_slots();
}

}  // namespace edgeland::detail

namespace edgeland::detail {

std::size_t SegmentGrid::cell_pairs() const {
  std::size_t pairs = 0;
  for (std::size_t k = 0; k + 1 < cell_begin_.size(); ++k) {
    const std::uint32_t begin = cell_begin_[k], end = cell_begin_[k + 1];
    if (!crowded(k)) {
      pairs += std::size_t{end - begin} * (end - begin - 1) / 2;  // 0 for an empty cell
      continue;
    }
    // Sorted by lo: item x overlaps the later items starting at most at its hi, usually a
    // few, so they are counted by galloping from x rather than by halving the whole list.
    for (std::uint32_t x = begin; x < end; ++x)
      pairs += later_starts_up_to(x + 1, end, bounds_[x].hi);
  }
  return pairs;
}

std::size_t SegmentGrid::later_starts_up_to(std::uint32_t from, std::uint32_t end,
                                            std::uint16_t hi) const {
  std::uint32_t step = 1, known = from;  // bounds_[y].lo <= hi for every y in [from, known)
  while (end - known > step && bounds_[known + step - 1].lo <= hi) {
    known += step;
    step *= 2;
  }
  const std::uint32_t stop = end - known > step ? known + step : end;
  const auto past = std::upper_bound(bounds_.begin() + known, bounds_.begin() + stop, hi,
                                     [](std::uint16_t v, const Bounds& b) { return v < b.lo; });
  return static_cast<std::size_t>(past - (bounds_.begin() + from));
}

namespace {

constexpr std::int64_t kNormalLimit = 1023;  // 11-bit normals: offsets fit 64 bits unscaled

// (lo, hi) scaled down by 2^shift, rounded outward.
IntegerRange scaled_out(std::int64_t lo, std::int64_t hi, int shift) {
  return {lo >> shift, -((-hi) >> shift)};
}

}  // namespace

IntegerRange SegmentGrid::stored_range(std::size_t k, std::int64_t lo, std::int64_t hi) const {
  const Normal n = normal_[k];
  const std::int64_t least =
      side_ * (std::min<std::int64_t>(n.x, 0) + std::min<std::int64_t>(n.y, 0));
  const std::int64_t span = side_ * (std::abs(n.x) + std::abs(n.y));
  return scaled_out(std::clamp<std::int64_t>(lo - least, 0, span),
                    std::clamp<std::int64_t>(hi - least, 0, span), offset_shift_);
}

IntegerRange SegmentGrid::box_offsets(std::size_t k, const Box64& b) const {
  const Point64 o = corner(k);
  const Box64 part{{std::max(b.min.x, o.x), std::max(b.min.y, o.y)},
                   {std::min(b.max.x, o.x + side_), std::min(b.max.y, o.y + side_)}};
  // Linear in p: its bounds over the box are at opposite corners, picked by n's signs.
  const Normal n = normal_[k];
  const std::int64_t x_lo = n.x >= 0 ? part.min.x : part.max.x,
                     x_hi = n.x >= 0 ? part.max.x : part.min.x;
  const std::int64_t y_lo = n.y >= 0 ? part.min.y : part.max.y,
                     y_hi = n.y >= 0 ? part.max.y : part.min.y;
  return stored_range(k, n.x * (x_lo - o.x) + n.y * (y_lo - o.y),
                      n.x * (x_hi - o.x) + n.y * (y_hi - o.y));
}

IntegerRange SegmentGrid::part_offsets(std::size_t k, const Segment& s, LineAt& line) const {
  const Point64 o = corner(k);
  const Normal n = normal_[k];
  std::int64_t lo = std::numeric_limits<std::int64_t>::max(), hi = -lo;
  auto add = [&](std::int64_t x, std::int64_t y) {
    const std::int64_t u = n.x * (x - o.x) + n.y * (y - o.y);
    lo = std::min(lo, u);
    hi = std::max(hi, u);
  };
  // The part's points lie on the line over the part box's range of the segment's longer
  // coordinate; the offset is linear along the line, so its bounds are at the two ends, each
  // known up to rounding (both bounds taken). With |slope| <= 1 those ends stay within a side
  // of the cell.
  const Box64 cell{o, {o.x + side_, o.y + side_}};
  const Box64 seg = segment_box(s);
  if (line.steep()) {
    for (std::int64_t y : {std::max(seg.min.y, cell.min.y), std::min(seg.max.y, cell.max.y)}) {
      const IntegerRange x = line.at(y);
      add(x.lo, y);
      add(x.hi, y);
    }
  } else {
    for (std::int64_t x : {std::max(seg.min.x, cell.min.x), std::min(seg.max.x, cell.max.x)}) {
      const IntegerRange y = line.at(x);
      add(x, y.lo);
      add(x, y.hi);
    }
  }
  return stored_range(k, lo, hi);
}

std::string SegmentGrid::offsets_violation(const std::vector<Segment>& segments) const {
  if (items_.empty()) return "";  // lists not filled: nothing ordered yet
  for (std::uint32_t i = 0; i + 1 < slot_begin_.size() && !slot_at_.empty(); ++i)
    for (std::uint32_t e = slot_begin_[i]; e < slot_begin_[i + 1]; ++e)
      if (items_[slot_at_[e]] != i) return "a slot of segment " + std::to_string(i) + " is astray";
  for (std::size_t k = 0; k + 1 < cell_begin_.size(); ++k) {
    if (!crowded(k)) continue;
    const Point64 o = corner(k);
    const Box64 cell{o, {o.x + side_, o.y + side_}};
    for (std::uint32_t x = cell_begin_[k]; x < cell_begin_[k + 1]; ++x) {
      const Bounds b = bounds_[x];
      if (x > cell_begin_[k] && bounds_[x - 1].lo > b.lo)
        return "cell " + std::to_string(k) + " unsorted";
      if (b.hi < b.lo || b.hi - b.lo > width_[k])
        return "cell " + std::to_string(k) + ": an interval is wider than the cell's width";
      for (Point64 p : {segments[items_[x]].a, segments[items_[x]].b}) {
        if (!cell.contains(p)) continue;
        const std::int64_t u = normal_[k].x * (p.x - o.x) + normal_[k].y * (p.y - o.y);
        const IntegerRange scaled = stored_range(k, u, u);
        if (scaled.lo < b.lo || scaled.hi > b.hi)
          return "segment " + std::to_string(items_[x]) + ": an end's offset in cell " +
                 std::to_string(k) + " lies outside its interval";
      }
    }
  }
  return "";
}

namespace {

// The normal of segment s, halved until it fits 11 bits (any normal is correct; a near one
// keeps near-parallel parts' intervals narrow).
std::pair<std::int64_t, std::int64_t> short_normal(const Segment& s) {
  std::int64_t nx = s.a.y - s.b.y, ny = s.b.x - s.a.x;
  while (std::max(std::abs(nx), std::abs(ny)) > kNormalLimit) {
    nx >>= 1;
    ny >>= 1;
  }
  return {nx, ny};
}

// Sort keys: lo above the item's place in its cell (the places are in id order, so the keys
// sort by (lo, id)); 64-bit keys compare faster than records.
std::uint64_t sort_key(std::uint16_t lo, std::uint32_t place) {
  return std::uint64_t{lo} << 32 | place;
}
std::uint16_t key_lo(std::uint64_t key) { return static_cast<std::uint16_t>(key >> 32); }

// Where the ascending run starting at x ends.
std::size_t run_end(const ScratchVector<std::uint64_t>& keys, std::size_t x) {
  if (x == keys.size()) return x;
  while (++x < keys.size() && keys[x - 1] < keys[x]) {
  }
  return x;
}

// Sorts distinct keys. A crowded cell lists its segments by id, and a ring's ids run along
// it, so the list is a few runs already ordered by offset (one per ring through the cell at
// zigzag stars): those are merged pairwise, linear per round; a list of many short runs is
// sorted. The keys are distinct, so every correct sort gives the same order.
void sort_runs(ScratchVector<std::uint64_t>& keys, ScratchVector<std::uint64_t>& merged) {
  // log2(runs) merge rounds against about log2(size) rounds of a sort's partitioning. A ring
  // may run against the cell's normal (the normal of an outward zigzag edge and an inward one
  // point opposite ways): its keys descend, and read backwards they are few ascending runs.
  std::size_t runs = 1;
  for (std::size_t x = 1; x < keys.size(); ++x) runs += keys[x] < keys[x - 1];
  if (2 * runs > keys.size() + 1) {
    std::reverse(keys.begin(), keys.end());
    runs = keys.size() + 1 - runs;
  }
  if (runs * runs > keys.size()) {
    std::sort(keys.begin(), keys.end());
    return;
  }
  while (runs > 1) {  // merge neighbouring runs, halving their number
    merged.clear();
    runs = 0;
    for (std::size_t x = 0; x < keys.size();) {
      const std::size_t mid = run_end(keys, x), end = run_end(keys, mid);
      std::merge(keys.begin() + x, keys.begin() + mid, keys.begin() + mid, keys.begin() + end,
                 std::back_inserter(merged));
      x = end;
      ++runs;
    }
    keys.swap(merged);
  }
}

}  // namespace

void SegmentGrid::order_crowded_cells(const std::vector<Segment>& segments) {
  if (!width_.empty() || cell_begin_.empty()) return;
  fill_lists();
  const std::size_t cells = cell_begin_.size() - 1;
  width_.assign(cells, -1);
  normal_.assign(cells, Normal{0, 0});
  for (std::size_t k = 0; k < cells; ++k) {
    if (cell_begin_[k + 1] - cell_begin_[k] <= kCrowded) continue;
    // The normal of the cell's middle segment in id order: along a ring that is also about the
    // middle of the cell, so the directions around it deviate least.
    const auto [nx, ny] = short_normal(segments[items_[(cell_begin_[k] + cell_begin_[k + 1]) / 2]]);
    normal_[k] = {static_cast<std::int16_t>(nx), static_cast<std::int16_t>(ny)};
    width_[k] = 0;
  }
  bound_parts(segments);
  sort_crowded_cells();
}

void SegmentGrid::bound_parts(const std::vector<Segment>& segments) {
  // Each segment's intervals in walk order: its cells share column (or row) boundaries.
  bounds_.assign(items_.size(), Bounds{0, 0});
  for (std::uint32_t i = 0; i + 1 < slot_begin_.size(); ++i) {
    LineAt line(segments[i]);
    for (std::uint32_t e = slot_begin_[i]; e < slot_begin_[i + 1]; ++e) {
      const Slot slot{slot_at_[e], slot_cell_[e]};
      if (!crowded(slot.cell)) continue;
      const IntegerRange u = part_offsets(slot.cell, segments[i], line);
      bounds_[slot.at] = {static_cast<std::uint16_t>(u.lo), static_cast<std::uint16_t>(u.hi)};
      width_[slot.cell] = std::max(width_[slot.cell], u.hi - u.lo);
    }
  }
}

void SegmentGrid::sort_crowded_cells() {
  ScratchVector<std::uint64_t> keys, merged;
  ScratchVector<std::uint32_t> ids;
  ScratchVector<std::uint16_t> his;
  for (std::size_t k = 0; k + 1 < cell_begin_.size(); ++k) {
    if (!crowded(k)) continue;
    const std::uint32_t begin = cell_begin_[k], end = cell_begin_[k + 1];
    keys.clear();
    for (std::uint32_t x = begin; x < end; ++x) keys.push_back(sort_key(bounds_[x].lo, x - begin));
    sort_runs(keys, merged);
    ids.assign(items_.begin() + begin, items_.begin() + end);
    his.clear();
    for (std::uint32_t x = begin; x < end; ++x) his.push_back(bounds_[x].hi);
    for (std::uint32_t x = begin; x < end; ++x) {
      const auto from = static_cast<std::uint32_t>(keys[x - begin]);
      items_[x] = ids[from];
      bounds_[x] = {key_lo(keys[x - begin]), his[from]};
    }
  }
  point_slots_at_items();
}

void SegmentGrid::point_slots_at_items() {
  // A segment's slots are in walk order, which is ascending cell order (column by column, each
  // column's rows upwards), so visiting the cells in order meets each segment's slots in their
  // order: one cursor per segment finds them, with no map from items to slots (that was a
  // fifth of the grid's memory while it was ordered).
  ScratchVector<std::uint32_t> next_slot;
  next_slot.assign(slot_begin_.begin(), slot_begin_.end() - 1);
  for (std::uint32_t x = 0; x < items_.size(); ++x) slot_at_[next_slot[items_[x]]++] = x;
}

}  // namespace edgeland::detail
