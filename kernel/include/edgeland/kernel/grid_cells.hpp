#pragma once
// Sizing uniform grids of square cells over boxes (the clipper's segment and box grids). The
// counts exceed 64 bits for the largest boxes, so they are exact 128-bit values computed from
// formulas.hpp (cells_covering, cells_area, block_size; theorem grid_sizing_int128).
#include <cstdint>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/int128.hpp"

namespace edgeland {

// Cell sides and cell or item counts these functions accept: 1 <= side <= kMaxGridSide and
// n <= kMaxGridSide (a side beyond twice the coordinate range, or more items than any memory
// holds, is never needed).
inline constexpr std::int64_t kMaxGridSide = std::int64_t{1} << 40;

// The number of integer points of box b: (max.x - min.x + 1)(max.y - min.y + 1). O(1).
EDGELAND_EXPORT Int128 point_count(const Box64& b) noexcept;

// How many cells of side `side` a grid anchored at b.min needs to cover b:
// ceil(w / side) * ceil(h / side) with w, h as in point_count. O(1).
EDGELAND_EXPORT Int128 cells_covering(const Box64& b, std::int64_t side) noexcept;

// side * side * n: the area n cells of side `side` cover. O(1).
EDGELAND_EXPORT Int128 cells_area(std::int64_t side, std::uint64_t n) noexcept;

// columns * rows: the cells of a block of a grid (0 <= columns, rows <= kMaxGridSide). O(1).
EDGELAND_EXPORT Int128 block_size(std::int64_t columns, std::int64_t rows) noexcept;

}  // namespace edgeland
