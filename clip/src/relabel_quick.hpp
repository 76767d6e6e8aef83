#pragma once
// The quick cases of a cell's overlay (relabel_cell(), relabel.hpp): most cells an edit reaches
// need no arrangement: an empty cell that stays empty, a cell the shape covers whole, a shape
// that meets no boundary in the cell and lies in one region it does not change. Those are
// answered by box tests and exact point and segment tests (kernel/) with the result relabel()
// would give, bit for bit (the argument for each is at its function in relabel_quick.cpp).
#include <cstdint>
#include <optional>
#include <span>

#include "edgeland/clip/relabel.hpp"
#include "relabel_pipeline.hpp"

namespace edgeland::detail {

// A cell as the quick cases read it: its content (a canonical decomposition in `box`) and the
// box of each of its polygons.
struct CellInput {
  const LabeledSet& content;
  std::span<const Box64> boxes;
  const Box64& box;
  const PolygonSet& polygons() const { return content.set.polygons(); }
  const std::vector<RegionLabel>& labels() const { return content.labels; }
};

// What the table makes of label l inside the shape (relabel.hpp: labels past its end are kept).
inline RegionLabel relabeled(std::span<const RegionLabel> table, RegionLabel l) {
  return l < table.size() ? table[l] : l;
}

// The quick cases, in the order they are tried.
enum class QuickCase : std::uint8_t {
  kNoMemberNear,      // no member's box meets the cell box
  kEmptyStaysEmpty,   // an empty cell, and the table keeps 0
  kCoveredUnchanged,  // a member covers the cell, and every material there stays
  kCoveredUniform,    // a member covers the cell, and every material there becomes one
  kClearOfTheShape,   // every polygon two units from the shape's edges, none inside changing
  // The shape's edges two units from every polygon edge off the cell's side lines, and every
  // region of the cell the shape meets keeps its material (the shape may cross the side lines).
  kThroughKeptRegions,
  // Every member inside the cell box, meeting no polygon edge, in a face that keeps its
  // material, with what it encloses.
  kInsideOneFace,
};

// The answer of a quick case: the cell stays as it is (no content), or becomes `content`.
struct QuickAnswer {
  QuickCase which;
  std::optional<LabeledSet> content;
};

// The first quick case that applies, or nullopt. `near`: the shape's members near the cell box
// (shape_near_window). Each answer is relabel()'s, bit for bit.
std::optional<QuickAnswer> quick_overlay(const CellInput& cell, const ValidSet& shape,
                                         const ShapeNearWindow& near,
                                         std::span<const RegionLabel> table);

}  // namespace edgeland::detail
