#pragma once
// Stage 2 of triangulate(): the pieces a polygon's diagonals cut it into.
#include <cstdint>
#include <span>
#include <vector>

#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/scratch.hpp"
#include "monotone_partition.hpp"

namespace edgeland::detail {

// Faces as runs of vertex indices, each counter-clockwise: face f is
// vertices[offsets[f] .. offsets[f + 1]).
// Scratch storage (scratch.hpp): a temporary of triangulate(), made for every polygon meshed.
struct Faces {
  Faces() { offsets.push_back(0); }
  ScratchVector<std::uint32_t> vertices;
  ScratchVector<std::uint32_t> offsets;

  std::size_t count() const { return offsets.size() - 1; }
  std::span<const std::uint32_t> face(std::size_t f) const {
    return std::span<const std::uint32_t>(vertices).subspan(offsets[f],
                                                            offsets[f + 1] - offsets[f]);
  }
};

// The faces of a valid polygon cut by diagonals as monotone_diagonals() returns them (inside,
// pairwise disjoint but for shared ends, distinct): d diagonals give d + 1 faces, together
// holding n + 2d vertex entries. Each face is traced with the interior on its left; at a vertex,
// the next side is the one next clockwise from the side it came in by (angles from the
// vertex's outgoing polygon edge, exact). O(n + d log d).
Faces faces_cut_by(const Polygon& polygon, const std::vector<Diagonal>& diagonals);

}  // namespace edgeland::detail
