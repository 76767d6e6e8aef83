#pragma once
// Pairs of segments that may share a point, when the segments are long and run in every
// direction (spiky inputs, and their fragments after snap rounding). Boxes filter such segments
// badly: a diagonal segment's box grows with the square of its length, and the boxes of n long
// spikes overlap about n^2 / 4 times while the spikes cross far less often. Here each segment is
// registered only in the grid cells its points lie in (a walk along it, column by column), so a
// candidate pair is two segments passing through a common cell.
//
// Why no meeting is missed: cell (c, r) is the closed square [x0 + c * side, x0 + (c + 1) * side]
// x [y0 + r * side, y0 + (r + 1) * side]. A point P of a segment lies in the cell
// (floor((P.x - x0) / side), floor((P.y - y0) / side)), and the walk registers the segment there:
// it visits every column between its ends' columns, and in each column the rows from the floor
// of the lowest to the floor of the highest y the segment's line takes over the column's closed
// x-range clipped to the segment (y is monotone along the segment, so floor(P.y) lies between
// them). Two segments sharing a point therefore share that point's cell. All arithmetic is exact
// (128-bit where products can exceed 64 bits).
//
// Cost: the walk is O(cells crossed) per segment, and a pair is tested in each cell it shares
// (reported once); cells are sized for one to four per segment.
//
// Crowded cells: long near-parallel segments (zigzag stars: 10^7-long edges 1,500 apart) fill
// every cell they cross with hundreds of others, and the cells cannot shrink (each segment
// would cross thousands), so proposing every pair of a cell grew with the square of the input
// (issue 28: 5,600 pairs per segment at 4 * 10^5 segments, for one crossing each). In a cell of
// more than kCrowded segments each segment's part is bounded by an interval of the offset
// n . (P - corner) across the cell (n: the normal of the cell's middle segment, cut to 11 bits;
// any n is correct, a near one makes near-parallel parts' intervals narrow) and the cell's
// segments are sorted by it: a pair is proposed there only when its intervals overlap. Two
// segments sharing a point P in the cell both hold P's offset, so no meeting is lost. The
// intervals come from kernel/line_bounds.hpp (the line's y at the part's x ends, rounded
// outward), cut to the offsets the closed cell itself spans (every point of a part lies in it)
// and scaled down by a power of two (rounded outward again) to fit 16 bits: a cell's span is at
// most 2^11 sides, so steps of a 2^-16 of it (about 16 units at the zigzag stars' cells) widen
// the intervals by little, and the bounds take 4 bytes per registration instead of 8.
//
// Built in two steps: the constructor walks the segments and counts each cell's segments (all
// that cell_pairs() needs to weigh the grid against the run index), and the cells' lists are
// filled on first use. A grid the run index beats (comb teeth side by side) never fills them:
// at combs of 10^6 vertices the lists were 200 of the 940 MB peak, kept through the index's
// pair walk (issue 28).
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/line_bounds.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/scratch.hpp"

namespace edgeland::detail {

// Whether the closed boxes of s and t overlap: the cheap test before an exact one.
inline bool boxes_overlap(const Segment& s, const Segment& t) {
  return segment_box(s).overlaps(segment_box(t));
}

class SegmentGrid {
 public:
  // Keeps no reference to `segments`.
  explicit SegmentGrid(const std::vector<Segment>& segments);
  // The cells laid over `extent`, which holds every segment, instead of over the segments' own
  // box, so that other segments inside it can be walked through them (for_each_along).
  SegmentGrid(const std::vector<Segment>& segments, const Box64& extent);

  // visit(i, j), i < j, exactly once for every pair of segments registered in a common cell;
  // this includes every pair of segments that share a point.
  template <class F>
  void for_each_candidate_pair(F&& visit);

  // visit(i) for every segment registered in a cell that meets the closed box b: this includes
  // every segment with a point in b. A segment registered in several such cells is visited once
  // per cell (callers dedupe).
  template <class F>
  void for_each_in_box(const Box64& b, F&& visit);

  // visit(i) for every segment i registered in a cell that s passes through (once per such
  // cell): this includes every segment sharing a point with s. s lies within the extent.
  template <class F>
  void for_each_along(const Segment& s, F&& visit);

  // Number of (segment, cell) registrations: the size of the structure, for tests.
  std::size_t entries() const { return registrations_; }

  // Pairs proposed in a common cell (in a crowded cell, those whose offsets overlap), counted
  // once per cell: what for_each_candidate_pair walks through.
  std::size_t cell_pairs() const;

  // The invariants the crowded cells' pair search relies on (checked mode, check_fragments.cpp):
  // each segment's slots point at its own entries; a crowded cell's list is sorted by lo, every
  // interval within the cell's width; and every segment end lying in a crowded cell has its
  // offset inside the segment's interval there. Returns the first violation, or "" if none.
  std::string offsets_violation(const std::vector<Segment>& segments) const;

  // Cells ordered by offset: for tests.
  std::size_t crowded_cells() const {
    return static_cast<std::size_t>(
        std::count_if(width_.begin(), width_.end(), [](std::int64_t w) { return w >= 0; }));
  }

  // Sorts each crowded cell's list by offset (above), once; `segments` as given to the
  // constructor. Until then every cell proposes all its pairs. Worth it only when the cells
  // hold many pairs and the run index has even more (candidate_pairs.hpp decides).
  void order_crowded_cells(const std::vector<Segment>& segments);
  // Orders them when the cells hold many pairs (more than 16 per segment): for a caller with
  // no run index to compare with (snap rounding's re-check of all fragments).
  void order_if_crowded(const std::vector<Segment>& segments) {
    if (cell_pairs() > 16 * segments.size() + 4096) order_crowded_cells(segments);
  }

  // Frees the per-segment slots (8 of the 16 bytes per registration at zigzag stars) once the last
  // pair walk is done: box queries do not read them. (Lists not filled yet still need the
  // slots' cells, which go once they are.) for_each_candidate_pair, order_crowded_cells and
  // offsets_violation must not be called afterwards.
  void drop_pair_walk() {
    pair_walks_done_ = true;
    if (!items_.empty()) drop_slots();
  }

  // Cells holding more segments than this are ordered by offset (above); below it the sort and
  // the exact bounds cost more than the pairs they save.
  static constexpr std::uint32_t kCrowded = 32;

 private:
  // Where a segment sits in a cell's list, and which cell.
  struct Slot {
    std::uint32_t at, cell;
  };
  // Fills the cells' lists (and the slots' places in them) if they are not filled yet.
  void fill_lists();
  void drop_slots() {
    discard(slot_at_);
    discard(slot_cell_);
    discard(slot_begin_);
  }
  // f(j) for every segment j listed with slot s's segment in its cell whose offsets overlap
  // (every one in an uncrowded cell), j listed after it in an uncrowded cell.
  template <class F>
  void for_each_partner(const Slot& s, F&& f) const;
  // visit(i) for the segments of cell k that may meet box b (b meets the cell).
  template <class F>
  void for_each_in_cell(std::size_t k, const Box64& b, F&& visit) const;
  // The cell's lower-left corner, and the bounds of n . (p - corner) over the points p of
  // `part` (the part of a segment or box in cell k), as stored: cut and scaled (stored_range).
  Point64 corner(std::size_t k) const {
    return {min_x_ + static_cast<std::int64_t>(k) / rows_ * side_,
            min_y_ + static_cast<std::int64_t>(k) % rows_ * side_};
  }
  IntegerRange box_offsets(std::size_t k, const Box64& b) const;
  // Bounds lo <= hi of n . (p - corner) in cell k as stored: measured from the least offset of
  // the closed cell, cut to the cell's span, divided by 2^offset_shift_ (rounded outward).
  IntegerRange stored_range(std::size_t k, std::int64_t lo, std::int64_t hi) const;
  // How many items in [from, end) of a crowded cell's sorted list start at most at hi.
  std::size_t later_starts_up_to(std::uint32_t from, std::uint32_t end, std::uint16_t hi) const;
  // The line of one segment at the ends of its parts, along x (along y when steep): the last
  // two answers are kept, since the walk's consecutive cells share a column or row boundary.
  class LineAt {
   public:
    explicit LineAt(const Segment& s)
        : s_(s), steep_(std::abs(s.b.y - s.a.y) > std::abs(s.b.x - s.a.x)) {}
    bool steep() const { return steep_; }
    IntegerRange at(std::int64_t t) {
      for (int k = 0; k < 2; ++k)
        if (known_[k] && key_[k] == t) return value_[k];
      if (s_.a == s_.b) return {steep_ ? s_.a.x : s_.a.y, steep_ ? s_.a.x : s_.a.y};
      next_ ^= 1;
      known_[next_] = true;
      key_[next_] = t;
      value_[next_] = steep_ ? line_x_at(s_.a, s_.b, t) : line_y_at(s_.a, s_.b, t);
      return value_[next_];
    }

   private:
    const Segment& s_;
    bool steep_;
    bool known_[2] = {false, false};
    std::int64_t key_[2] = {0, 0};
    IntegerRange value_[2] = {};
    int next_ = 0;
  };
  IntegerRange part_offsets(std::size_t k, const Segment& s, LineAt& line) const;
  // The steps of order_crowded_cells: every item's interval in a crowded cell, then each
  // crowded cell's list sorted by (lo, id), the slots following their items.
  void bound_parts(const std::vector<Segment>& segments);
  void sort_crowded_cells();
  // Sets every slot's place in its cell's list (after the lists were reordered).
  void point_slots_at_items();
  bool crowded(std::size_t k) const { return !width_.empty() && width_[k] >= 0; }
  // f(cell index) for every cell the walk registers s in, each cell once, in ascending order
  // (columns left to right, each column's rows upwards; point_slots_at_items relies on it).
  template <class F>
  void for_each_cell(const Segment& s, F&& f) const;
  // How many cells for_each_cell registers s in: its columns, plus one per row it climbs or
  // descends (the walk is monotone, so each column adds the rows between its entry and exit).
  std::size_t cells_walked(const Segment& s) const {
    const std::int64_t columns =
        std::abs(((s.b.x - min_x_) >> shift_) - ((s.a.x - min_x_) >> shift_));
    const std::int64_t rows = std::abs(((s.b.y - min_y_) >> shift_) - ((s.a.y - min_y_) >> shift_));
    return static_cast<std::size_t>(columns + rows + 1);
  }
  // Lays the grid out with square cells of the given side over the segments' bounding box.
  void set_side(std::int64_t side);

  std::int64_t min_x_ = 0, min_y_ = 0, max_x_ = 0, max_y_ = 0;
  std::int64_t side_ = 1, columns_ = 0, rows_ = 0;
  int shift_ = 0;  // side_ == 2^shift_: cells are found by shifts, not divisions
  // CSR over cells: items_ of cell k, ascending ids, or by (lo, id) in a crowded cell.
  ScratchVector<std::uint32_t> cell_begin_;
  ScratchVector<std::uint32_t> items_;  // segment ids
  // Per item in a crowded cell: its offset bounds, side by side (a scan reads both, and one
  // array is one cache miss per cell instead of two).
  struct Bounds {
    std::uint16_t lo, hi;
  };
  ScratchVector<Bounds> bounds_;
  struct Normal {
    std::int16_t x, y;
  };
  ScratchVector<Normal> normal_;  // per crowded cell
  // per cell once ordered: its bounds_' largest hi - lo when crowded, else -1 (empty till then)
  ScratchVector<std::int64_t> width_;
  int offset_shift_ = 0;  // offsets are divided by 2^offset_shift_
  // CSR over segments: the slots of segment i, in walk order: slot k's cell and its place in
  // the cell's list (once the lists are filled).
  ScratchVector<std::uint32_t> slot_begin_;
  ScratchVector<std::uint32_t> slot_cell_, slot_at_;
  std::size_t registrations_ = 0;
  bool pair_walks_done_ = false;  // drop_pair_walk was called
};

template <class F>
void SegmentGrid::for_each_cell(const Segment& s, F&& f) const {
  const Point64 a = s.a.x <= s.b.x ? s.a : s.b, b = s.a.x <= s.b.x ? s.b : s.a;
  const std::int64_t seg_lo = std::min(a.y, b.y), seg_hi = std::max(a.y, b.y);
  auto row = [&](std::int64_t y) { return (y - min_y_) >> shift_; };  // y >= min_y_
  auto rows_between = [&](std::int64_t c, std::int64_t lo, std::int64_t hi) {
    for (std::int64_t r = row(lo); r <= row(hi); ++r) f(static_cast<std::size_t>(c * rows_ + r));
  };
  const std::int64_t c0 = (a.x - min_x_) >> shift_, c1 = (b.x - min_x_) >> shift_;
  if (c0 == c1) {  // one column (vertical segments among them): the rows of its y-range
    rows_between(c0, seg_lo, seg_hi);
    return;
  }
  if (a.y == b.y) {  // horizontal (tiles, boxes): one row, no line to follow
    const std::int64_t r = row(a.y);
    for (std::int64_t c = c0; c <= c1; ++c) f(static_cast<std::size_t>(c * rows_ + r));
    return;
  }
  // Column c spans the line's rows from where the segment enters it (a's row in the first) to
  // the row of its y at the column's right boundary X (b's row in the last); adjacent columns
  // share the boundary's row. That row is tracked by stepping, not dividing: the line reaches
  // row boundary Y at X exactly when (X, Y) is not left of a -> b (a.x < b.x), one orientation
  // per column and per row crossed. (Two 64-bit divisions per segment were most of the grid's
  // construction on spiky inputs.) Every X lies in (a.x, b.x] and every Y tested between a.y
  // and b.y, so (X, Y) is an in-range point.
  const std::int64_t dy = b.y - a.y;
  auto reaches = [&](std::int64_t x, std::int64_t y) {  // the line's y at x is >= y
    return orient_det(a, b, {x, y}) <= 0;
  };
  const std::int64_t r_last = row(b.y);
  std::int64_t r_in = row(a.y), r = r_in;
  for (std::int64_t c = c0; c <= c1; ++c) {
    if (c < c1) {
      const std::int64_t x = min_x_ + (c + 1) * side_;
      if (dy > 0) {
        while (r < r_last && reaches(x, min_y_ + (r + 1) * side_)) ++r;
      } else {
        while (r > r_last && !reaches(x, min_y_ + r * side_)) --r;
      }
    } else {
      r = r_last;
    }
    for (std::int64_t k = std::min(r_in, r); k <= std::max(r_in, r); ++k)
      f(static_cast<std::size_t>(c * rows_ + k));
    r_in = r;
  }
}

template <class F>
void SegmentGrid::for_each_in_box(const Box64& b, F&& visit) {
  fill_lists();
  if (items_.empty() || b.max.x < min_x_ || b.max.y < min_y_ || b.min.x > max_x_ ||
      b.min.y > max_y_)
    return;
  // Points of b outside the grid's extent belong to no segment; the rest lie in these cells.
  const std::int64_t c0 = (std::max(b.min.x, min_x_) - min_x_) >> shift_;
  const std::int64_t c1 = (std::min(b.max.x, max_x_) - min_x_) >> shift_;
  const std::int64_t r0 = (std::max(b.min.y, min_y_) - min_y_) >> shift_;
  const std::int64_t r1 = (std::min(b.max.y, max_y_) - min_y_) >> shift_;
  for (std::int64_t c = c0; c <= c1; ++c)
    for (std::int64_t r = r0; r <= r1; ++r)
      for_each_in_cell(static_cast<std::size_t>(c * rows_ + r), b, visit);
}

template <class F>
void SegmentGrid::for_each_along(const Segment& s, F&& visit) {
  fill_lists();
  if (items_.empty()) return;
  for_each_cell(s, [&](std::size_t k) {
    for (std::uint32_t x = cell_begin_[k]; x < cell_begin_[k + 1]; ++x) visit(items_[x]);
  });
}

template <class F>
void SegmentGrid::for_each_in_cell(std::size_t k, const Box64& b, F&& visit) const {
  std::uint32_t x = cell_begin_[k];
  const std::uint32_t end = cell_begin_[k + 1];
  if (!crowded(k)) {
    for (; x < end; ++x) visit(items_[x]);
    return;
  }
  // A segment with a point P in b holds P's offset, which lies within b's (on the cell).
  const IntegerRange q = box_offsets(k, b);
  const std::int64_t reach = q.lo - width_[k];  // no item starting lower reaches q.lo
  x = static_cast<std::uint32_t>(
      std::lower_bound(bounds_.begin() + x, bounds_.begin() + end, reach,
                       [](const Bounds& v, std::int64_t t) { return v.lo < t; }) -
      bounds_.begin());
  for (; x < end && bounds_[x].lo <= q.hi; ++x)
    if (bounds_[x].hi >= q.lo) visit(items_[x]);
}

template <class F>
void SegmentGrid::for_each_partner(const Slot& s, F&& f) const {
  const std::uint32_t begin = cell_begin_[s.cell], end = cell_begin_[s.cell + 1];
  if (!crowded(s.cell)) {  // ascending ids: the partners with larger ids follow
    for (std::uint32_t y = s.at + 1; y < end; ++y) f(items_[y]);
    return;
  }
  // Sorted by lo: later items overlap until one starts past hi; earlier ones start at most
  // the cell's widest interval below lo if they reach it.
  const std::uint16_t lo = bounds_[s.at].lo, hi = bounds_[s.at].hi;
  for (std::uint32_t y = s.at + 1; y < end && bounds_[y].lo <= hi; ++y) f(items_[y]);
  const std::int64_t reach = std::int64_t{lo} - width_[s.cell];
  for (std::uint32_t y = s.at; y-- > begin && bounds_[y].lo >= reach;)
    if (bounds_[y].hi >= lo) f(items_[y]);
}

template <class F>
void SegmentGrid::for_each_candidate_pair(F&& visit) {
  fill_lists();
  // Each segment i asks its cells for partners with larger ids; a stamp per segment drops
  // partners already met in an earlier common cell.
  ScratchVector<std::uint32_t> stamp;
  stamp.assign(slot_begin_.empty() ? 0 : slot_begin_.size() - 1,
               std::numeric_limits<std::uint32_t>::max());
  for (std::uint32_t i = 0; i + 1 < slot_begin_.size(); ++i) {
    for (std::uint32_t k = slot_begin_[i]; k < slot_begin_[i + 1]; ++k) {
      for_each_partner({slot_at_[k], slot_cell_[k]}, [&](std::uint32_t j) {
        if (j <= i || stamp[j] == i) return;
        stamp[j] = i;
        visit(i, j);
      });
    }
  }
}

}  // namespace edgeland::detail
