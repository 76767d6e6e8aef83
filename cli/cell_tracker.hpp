#pragma once
// The cells (leaf boxes) of a landscape, followed from its change sets: Landscape offers no
// walk over its cells, and a picture of the tree (`--cells`) needs the empty ones too, which
// no polygon query shows.
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::cli {

class CellTracker {
 public:
  // A landscape that is one cell, the world box: any landscape of the default (adaptive)
  // configuration before its first edit.
  explicit CellTracker(const Box64& world) : cells_{world} {}

  // Follows one successful edit. ChangeSet::cells lists every leaf whose content is new; the
  // leaves always partition the world, so an old leaf whose interior meets a new one has been
  // replaced (split, merged or rebuilt) and is dropped. O(cells) per edit.
  void apply(const ChangeSet& changes);

  const std::vector<Box64>& cells() const noexcept { return cells_; }

 private:
  std::vector<Box64> cells_;
};

}  // namespace edgeland::cli
