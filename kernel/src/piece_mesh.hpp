#pragma once
// The pieces of convex_pieces() while they merge: triangles as half-edge cycles that join across
// the diagonals they share.
#include <cstdint>
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "edgeland/kernel/triangulate.hpp"

namespace edgeland::detail {

inline constexpr std::uint32_t kNoTwin = 0xFFFFFFFFu;

// Half-edge 3t + k runs from corner k of triangle t to corner k + 1. A piece is a cycle of
// half-edges (next/prev) with the piece on its left; a diagonal is a pair of twins, one in each
// of the two pieces it separates. Pieces are kept as union-find classes of their triangles, each
// class root holding the piece's corner count (vertices where it turns strictly).
class PieceMesh {
 public:
  // From triangulate()'s triangles of `polygon`. O(n log n): the twins are found by sorting.
  PieceMesh(const Polygon& polygon, const std::vector<Triangle>& triangles);

  std::size_t half_edge_count() const { return origin_.size(); }
  std::uint32_t twin(std::uint32_t h) const { return twin_[h]; }
  bool alive(std::uint32_t h) const { return alive_[h] != 0; }
  std::uint32_t next(std::uint32_t h) const { return next_[h]; }
  std::uint32_t origin(std::uint32_t h) const { return origin_[h]; }
  std::uint32_t prev(std::uint32_t h) const { return prev_[h]; }
  Point64 point(std::uint32_t h) const { return polygon_[origin_[h]]; }
  const Polygon& polygon() const { return polygon_; }

  // The number of corners of the piece holding half-edge h.
  std::uint32_t corners(std::uint32_t h) { return corners_[root(h / 3)]; }

  // Joins the two pieces across diagonal h (alive, with a twin, the pieces distinct) into one
  // with `corners` corners: both half-edges leave their cycles. O(log n) amortized.
  void merge_across(std::uint32_t h, std::uint32_t corners);

 private:
  std::uint32_t root(std::uint32_t triangle);

  const Polygon& polygon_;
  // Scratch arrays: meshing a game's polygons one after another allocates none of them.
  ScratchVector<std::uint32_t> origin_, next_, prev_, twin_;
  ScratchVector<char> alive_;
  ScratchVector<std::uint32_t> parent_;   // union-find over triangles
  ScratchVector<std::uint32_t> corners_;  // at each root
};

}  // namespace edgeland::detail
