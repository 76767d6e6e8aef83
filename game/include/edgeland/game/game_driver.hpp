#pragma once
// The game driver (game/README.md, "The game driver"): one owner of a landscape and of
// everything a game derives from it. A game hands it each frame's edits and gets back what
// changed for it (game_types.hpp): the collision chains to remove and add, the render meshes to
// drop and build, the islands that broke off as debris bodies; and it can ask which of its
// bodies a fill buried. The Box2D adapter, the desktop demo and the browser playground only
// translate its updates (STYLE rule 15), the way a Box2D v3 game reads b2World's events.
//
//   GameDriver game(Landscape(world_box, rock), options);
//   each frame:
//     GameUpdate u = game.apply(frame_edits);     // Edit::carve(shape), Edit::fill(shape, m), ...
//     remove u.chains.removed, add u.chains.added; drop/build u.meshes; a body per u.debris
//     for each body: if (game.buried(box_of(body))) remove it
//     world.Step(...)
//
// ONE PASS PER CELL. An update reads each cell the change replaced once and cuts its solid
// boundary once (stage 1 of game/README.md); the chains, the island summaries and the meshes all
// come from that pass. A neighbour whose chains depend on the change (a side covered or
// uncovered from across, a ghost) is traced again from what the driver kept of it, without
// reading its polygons.
//
// ERRORS. apply() validates the edits as the landscape does and throws the landscape's typed
// errors (InvalidInput, CoordinateOutOfRange, InvalidMaterial, LimitExceeded, ...) with the
// driver and its landscape exactly as they were (the strong guarantee). Nothing else throws
// but running out of memory (or, on a checked landscape, an internal error its checks found),
// after which the driver must be reset() (apply() throws std::logic_error until then, naming
// what stopped the update): reset() then derives everything anew from the world it is
// given, and its update takes the game from what the last update it returned left it holding
// to the new state (chain ids continue; what was removed never comes back). Detaching debris
// never throws: an island that changed before its turn is found again by the update that
// changed it.
//
// DETERMINISM. Integer and exact: the same edits give the same updates, ids and landscape
// (state_hash) on every compiler and in WebAssembly.
#include <map>
#include <memory>
#include <span>

#include "edgeland/game/game_types.hpp"
#include "edgeland/spatial/landscape.hpp"

namespace edgeland {

namespace game_detail {
class GameState;
}

class EDGELAND_EXPORT GameDriver {
 public:
  // Everything of `world` derived at once: chains, island summaries (islands already in the
  // world wait in the debris queue: the first update detaches them). O(N log N). Throws
  // InvalidArgument for options an update could not honour (max_piece_vertices below 3).
  explicit GameDriver(Landscape world, const GameOptions& options = {});
  ~GameDriver();
  GameDriver(GameDriver&&) noexcept;
  GameDriver& operator=(GameDriver&&) noexcept;

  // The frame's edits, in order, as one batch; then the chains, meshes and islands kept in
  // step, and debris detached (within GameOptions::debris_budget). No edits: only the debris
  // queue moves. Throws the landscape's errors (see ERRORS) with nothing changed.
  GameUpdate apply(std::span<const Edit> edits);
  GameUpdate apply(const Edit& edit) { return apply(std::span<const Edit>(&edit, 1)); }

  // The landscape replaced by another (an undo to a snapshot, a load): every cell whose polygons
  // differ from the last seen is taken again, so the update names exactly what changed. O(N).
  GameUpdate reset(Landscape world);
  // For bindings: the update the last apply() or reset() returned never reached the game (handing
  // it over ran out of memory). The driver forgets it gave it, as if that call had run out of
  // memory: reset() it next, and its update starts from what the game held before.
  void update_lost() noexcept;

  // Whether the last update's fills buried a body whose bounding box is `box`: the box's
  // interior meets the interior of a filling edit's shape (one that turns some non-solid
  // material solid) where the edits left solid material (also where that solid then fell as
  // debris: a body inside a debris body is buried too). A game removes such bodies: a body
  // inside solid has no surface to stand on. To within the clipper's one rounding of the
  // shape cut to the box. O(depth + the shape).
  bool buried(const Box64& box) const;

  const Landscape& landscape() const noexcept;
  const GameOptions& options() const noexcept;
  // Every chain now, by id (what the updates so far add up to).
  const std::map<ChainId, SurfaceChain>& chains() const noexcept;
  std::size_t debris_waiting() const noexcept;

 private:
  std::unique_ptr<game_detail::GameState> state_;
};

}  // namespace edgeland
