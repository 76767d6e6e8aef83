#pragma once
// Where a cell splits (thesis 4.5.1): at its integer midpoint lines, into closed boxes that share
// those lines. A quadtree cuts every side longer than min_cell_size (four children, or two when
// only one side may be cut); a kd-tree cuts the longer side (x on ties). Sides longer than
// min_cell_size >= 1 are at least 2 long, so a midpoint lies strictly inside and no child is
// flat.
#include <cstdint>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/spatial/errors.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland::detail {

// The smallest edge cap: a cell crossed by one or two boundaries (a few polygons of a few edges
// each) must not split, or a long slanted boundary would split every cell along it down to
// min_cell_size.
inline constexpr std::uint32_t kMinEdgeCap = 32;

// A grid of depth d has up to 4^d cells.
inline constexpr int kMaxGridDepth = 10;

// Throws InvalidConfig unless the world box and the configuration are usable.
void require_config(const Box64& world, const LandscapeConfig& config);

// Whether a cell of this box may split.
bool can_split(const Box64& box, const LandscapeConfig& config) noexcept;

// The children's boxes, in a fixed order (x before y, low before high). Requires can_split.
std::vector<Box64> split_boxes(const Box64& box, const LandscapeConfig& config);

}  // namespace edgeland::detail
