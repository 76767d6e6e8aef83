#pragma once
// The obstacles and vertices of one hole splitting, filed by rows of y, so that a bridge's
// searches read only the rows they reach instead of every edge and vertex of the region: a
// westward ray reads one row, a bridge's visibility test the rows of its y-range, a ray's
// candidate triangle the vertices of its y-range. The rings' edges are filed once (flat rows);
// the bridges, two per hole, are filed in the rows they cross as they come. The westward ray gets
// its matches ascending, the order the linear scans met them; a visibility test (a yes or no)
// and the candidate triangle (whose choice does not depend on order) take them as filed.
// All storage is scratch (scratch.hpp): nothing allocated once a thread is warm.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/scratch.hpp"

namespace edgeland::detail {

class ObstacleRows {
 public:
  // Files the ring edges `edges` (obstacles 0 .. size - 1) and the vertices `vertices`
  // (indices into it) by y.
  ObstacleRows(const std::vector<Segment>& edges, const std::vector<Point64>& vertices);

  // Files obstacle `index` (after the ring edges, ascending over calls): a bridge.
  void add_bridge(std::uint32_t index, const Segment& s);
  // The obstacles with a y-range meeting [lo, hi] possibly, ascending and without repeats; or,
  // not `ordered`, in row order with an obstacle of several rows once per row.
  void obstacles_in(std::int64_t lo, std::int64_t hi, ScratchVector<std::uint32_t>& out,
                    bool ordered = true) const;
  // The vertices with y in [lo, hi], by y (the candidate triangle's choice, the vertex of least
  // angle and then greatest x, is one point whatever the order: hole_splitting.cpp).
  void vertices_in(std::int64_t lo, std::int64_t hi, ScratchVector<std::uint32_t>& out) const;

 private:
  std::size_t row(std::int64_t y) const;
  std::size_t rows() const { return first_.size() - 1; }

  std::int64_t y_min_ = 0;
  std::uint64_t row_height_ = 1;
  ScratchVector<std::uint32_t> first_;  // row r's ring edges: filed_[first_[r] .. first_[r + 1])
  ScratchVector<std::uint32_t> filed_;
  // Bridges filed by row: row r's list starts at bridge_head_[r] and follows `next`, in the
  // order they were added (ascending); kNone ends it.
  struct FiledBridge {
    std::uint32_t index;
    std::uint32_t next;
    Segment s;
  };
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  ScratchVector<FiledBridge> bridges_;
  ScratchVector<std::uint32_t> bridge_head_, bridge_tail_;
  ScratchVector<std::pair<std::int64_t, std::uint32_t>> by_y_;  // (y, vertex), ascending
};

}  // namespace edgeland::detail
