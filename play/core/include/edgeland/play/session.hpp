#pragma once
// A front end's hold on its world (play/web, play/desktop): the landscape, the tools' edits and
// undo/redo by snapshots. A Landscape copy costs O(1) (the tree is persistent and shared), so
// every edit keeps the world before it, and undo is one assignment; the recorded edit log lives
// in the landscape and goes back with it, so the log of the world shown always replays to it.
#include <cstddef>
#include <vector>

#include "edgeland/play/tool_shapes.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::play {

class Session {
 public:
  // `world` as it is now; its log (if it records one) goes on recording. Keeps at most
  // `max_undo` snapshots to go back to.
  explicit Session(Landscape world, std::size_t max_undo = 256);

  // Applies the tool's edit (tool_shape: valid by construction). Throws what the landscape's
  // edits throw, the world then unchanged (strong guarantee).
  ChangeSet apply(const ToolEdit& edit);

  // Back to the world before the last edit (or forward again); false when there is none.
  bool undo();
  bool redo();

  // Replaces the world (a loaded save file): the history starts again.
  void reset(Landscape world);

  const Landscape& world() const noexcept { return world_; }
  Landscape& world() noexcept { return world_; }

 private:
  Landscape world_;
  std::size_t max_undo_;
  std::vector<Landscape> undo_;  // oldest first
  std::vector<Landscape> redo_;  // the next redo last
};

}  // namespace edgeland::play
