#pragma once
// I3, a cell's content is the canonical decomposition of its material regions (relabel.hpp),
// decided without an overlay where that is sound: checked mode, check() and load() run it on
// every cell they verify, and a load re-deriving every cell by an overlay cost 19 times a save
// (issue 27, point 5).
#include <cstddef>
#include <span>

#include "node.hpp"

namespace edgeland::detail {

// Whether the cell's content equals relabel's canonical decomposition of it. The content must be
// a valid set (I1) inside the cell's box (I2). Exact; O(n) for a cell whose pieces of one
// material share no boundary segment, else one overlay, O(n log n).
bool cell_is_canonical(const Node& cell);

// Whether the members of a cell in canonical form at `members` (ascending), taken alone, are the
// canonical decomposition of their own material regions, decided without an overlay: true when
// no two of one material share a boundary segment (cell_is_canonical's argument); false when
// they do or the pairs are too many to look. What Landscape::remove keeps of a cell.
bool members_stay_apart(const Node& cell, std::span<const std::size_t> members);

// The overlay's verdict alone (what cell_is_canonical answers without it where it can): for
// the test that the two agree.
bool cell_is_canonical_by_overlay(const Node& cell);

}  // namespace edgeland::detail
