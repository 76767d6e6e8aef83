#pragma once
// Hole splitting (thesis 3.6.3): a region given by counter-clockwise outer rings and clockwise
// holes becomes hole-free strictly simple polygons, cut along diagonals between existing
// vertices (no new rounding). See clip/README.md for why the cuts leave no hole behind.
#include <cstddef>
#include <vector>

#include "assembly.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// Each hole must lie inside one of the outers (a region boundary from assembly). Appends to
// `out` the outers without holes unchanged and every outer with holes cut into pieces (the
// rings of `outers` are moved from). Adds the number of holes removed to `holes_split`.
// O(h * n) for h holes and n vertices of their polygons at worst; each bridge's searches read
// only the rows of y it reaches (obstacle_rows.hpp), so spread-out holes cost about O(n + h * r)
// for r edges a row.
void split_holes(std::vector<ScratchRing>& outers, std::vector<ScratchRing>& holes,
                 std::size_t& holes_split, std::vector<Ring>& out);

// The same on rings, returning the pieces.
inline std::vector<Ring> split_holes(const std::vector<Ring>& outers,
                                     const std::vector<Ring>& holes, std::size_t& holes_split) {
  ScratchVector<ScratchRing> o, h;
  for (const Ring& r : outers) o.emplace_back().assign(r.begin(), r.end());
  for (const Ring& r : holes) h.emplace_back().assign(r.begin(), r.end());
  std::vector<Ring> out;
  split_holes(o, h, holes_split, out);
  return out;
}

}  // namespace edgeland::detail
