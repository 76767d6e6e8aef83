#pragma once
// Step 2b of an edit (spatial/README.md, "An edit"): a big shape cut to the cells it touches
// first, once, so that each cell's overlay sees only the part of the shape in that cell (issue
// 27, point 6). Without it every cell takes each member whose box reaches it whole: carving back
// a set of 13 combs of 106k vertices over ~20k cells ran 5,000-vertex noding setups in every
// cell (75-88 s, against 5 s for filling it into one cell).
//
// The cut is one cut_to_windows() arrangement of the shape and every touched cell's box: the
// pieces on the two sides of a cell line come from the same rounded edges, so seams stay exact.
// The shape's boundary is rounded where it crosses a cell line at a point that is not an integer
// (as the uncut overlay rounds it there) and then again where a piece crosses the cell's own
// boundaries: two roundings of the shape's edges near cell lines instead of one, the landscape's
// own boundaries still rounded once. Small shapes are never cut (their results are unchanged, bit
// for bit): only a shape of kCutFromVertices vertices or more (a game's explosion has 16-64) whose
// members reach the touched cells kCutFactor times over or more.
#include <cstddef>
#include <optional>
#include <unordered_map>
#include <vector>

#include "edgeland/clip/relabel.hpp"
#include "node.hpp"

namespace edgeland::detail {

inline constexpr std::size_t kCutFromVertices = 256;
inline constexpr std::size_t kCutFactor = 4;

// The shape's pieces in each cell an edit reaches (box interiors meet the shape's box).
struct ShapeCut {
  std::unordered_map<const Node*, ValidSet> pieces;
  // Landscape::remove: each cell's pieces are these of its own members (ascending indices), so
  // a cell whose other members stay apart keeps them as they are, without an overlay (edit.cpp).
  std::unordered_map<const Node*, std::vector<std::size_t>> members;
  // The pieces of `cell`, or nullptr when it is not a cell the cut reached.
  const ValidSet* of(const Node& cell) const {
    const auto it = pieces.find(&cell);
    return it == pieces.end() ? nullptr : &it->second;
  }
};

// The shape cut to the cells below `root` that it touches, or nullopt when the cut would not pay
// (small shapes, or members that each reach few cells).
std::optional<ShapeCut> cut_shape_to_cells(const NodePtr& root, const ValidSet& shape,
                                           const Box64& shape_box, const ClipOptions& options);

}  // namespace edgeland::detail
