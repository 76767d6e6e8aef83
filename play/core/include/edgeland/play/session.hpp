#pragma once
// A front end's hold on its world (play/web, play/desktop): the game driver that owns the
// landscape, the tools' edits and undo/redo by snapshots. Every call hands back the driver's
// GameUpdate (what the front end's physics, meshes and debris take). A Landscape copy costs O(1)
// (the tree is persistent and shared), so every edit keeps the world before it, and undo is the
// driver reset to it; the recorded edit log lives in the landscape and goes back with it, so
// the log of the world shown always replays to it.
#include <cstddef>
#include <optional>
#include <vector>

#include "edgeland/game/game_driver.hpp"
#include "edgeland/play/tool_shapes.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland::play {

class Session {
 public:
  // `world` as it is now; its log (if it records one) goes on recording. Keeps at most
  // `max_undo` snapshots to go back to.
  Session(Landscape world, const GameOptions& options, std::size_t max_undo = 256);

  // Applies the tool's edit (tool_shape: valid by construction). Throws what the landscape's
  // edits throw, the world then unchanged (strong guarantee).
  GameUpdate apply(const ToolEdit& edit);

  // Back to the world before the last edit (or forward again); nothing when there is none.
  std::optional<GameUpdate> undo();
  std::optional<GameUpdate> redo();

  // Replaces the world (a loaded save file): the history starts again.
  GameUpdate reset(Landscape world);
  // No edit: the debris waiting in the driver's queue moves (GameDriver::apply of no edits).
  GameUpdate settle();

  const Landscape& world() const noexcept { return game_.landscape(); }
  const GameDriver& game() const noexcept { return game_; }

 private:
  GameDriver game_;
  std::size_t max_undo_;
  std::vector<Landscape> undo_;  // oldest first
  std::vector<Landscape> redo_;  // the next redo last
};

// The tool's edit as one edit of a frame.
Edit tool_edit(const ToolEdit& edit);

}  // namespace edgeland::play
