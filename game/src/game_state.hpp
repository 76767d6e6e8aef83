#pragma once
// What a GameDriver owns (game_driver.hpp), and the stages of one update:
//
//   edit     the frame's edits on the landscape, as one batch (the landscape's strong guarantee:
//            a throw leaves everything as it was, nothing below has run yet);
//   follow   the cells the change replaced leave the store and the new ones are scanned, once
//            each (cell_scan.hpp); the chains (surface_state.hpp) and the island summaries
//            (island_tree.hpp) are made from those records; new islands join the debris queue;
//   debris   queued islands' debris made in steps, oldest first within the budget (debris_job.hpp),
//            those finished carved out in one edit (debris.hpp); that edit is followed like
//            the first;
//   finish   the steps' changes, chains and meshes merged into one GameUpdate (what was added
//            and removed within the update appears in neither list).
#include <array>
#include <deque>
#include <memory>
#include <span>
#include <vector>

#include "cell_store.hpp"
#include "debris_job.hpp"
#include "edgeland/game/game_driver.hpp"
#include "edgeland/game/islands.hpp"
#include "island_tree.hpp"
#include "surface_state.hpp"

namespace edgeland::game_detail {

class GameState {
 public:
  GameState(Landscape world, const GameOptions& options, ChainId first_chain_id = 1);

  GameUpdate apply(std::span<const Edit> edits);
  GameUpdate reset(Landscape world);
  // A state made anew from `world` that takes over from `failed` (a state an update threw out
  // of after changing it): the update from what the game holds of `failed` (its last delivered
  // update) to everything this state derives. Chain ids continue `failed`'s.
  static std::unique_ptr<GameState> rebuilt(const GameState& failed, Landscape world,
                                            GameUpdate& out);
  // An update threw after changing the state (running out of memory): what it holds no longer
  // matches what the game was told, and only rebuilt() recovers.
  bool broken() const noexcept { return broken_; }
  // The last update returned never reached the game (a binding ran out of memory handing it
  // over): what the game holds is again what it was before that update, and the state is broken.
  void update_lost() noexcept;
  bool buried(const Box64& box) const;

  const Landscape& landscape() const noexcept { return land_; }
  const GameOptions& options() const noexcept { return options_; }
  const std::map<ChainId, SurfaceChain>& chains() const noexcept { return surface_.chains(); }
  std::size_t debris_waiting() const noexcept { return queue_.size(); }
  const CellStore& store() const noexcept { return store_; }

 private:
  struct Waiting {
    DebrisJob job;
    IslandKey key;        // the island's in IslandTree
    std::size_t age = 0;  // updates it has waited
  };

  ChangeSet edit(std::span<const Edit> edits);
  void follow(const Landscape& before, const ChangeSet& changes, GameUpdate& out);
  void replace_cells(std::span<const Box64> replaced, std::span<const Box64> fresh);
  void trace_surface(GameUpdate& out);
  void check_before_surface() const;
  void check_queue_order() const;
  void check_waits_bounded() const;
  void drain_debris(GameUpdate& out);
  std::vector<DebrisJob> advance_jobs();
  DebrisJob::Pace pace_of(const Waiting& w) const;
  void queue_islands(std::vector<Island> islands);
  std::size_t waited(const Box64& bounds) const;
  void finish(GameUpdate& out) const;
  void note_fills(std::span<const Edit> edits);
  void start_work();
  // The update is the game's: what it holds now (delivered_, delivered_chains_) follows it.
  void deliver(const GameUpdate& out);
  // Broken until rebuilt, `why` kept (cut to fit) for the next apply's error.
  void break_by(const char* why) noexcept;
  template <class Stages>
  GameUpdate guarded(Stages&& stages);

  GameOptions options_;
  Landscape land_;
  Landscape filled_;  // the landscape right after the last edits (buried())
  CellStore store_;
  SurfaceState surface_;
  std::unique_ptr<IslandTree> islands_;
  std::deque<Waiting> queue_;
  // The last update's filling shapes with their boxes (buried(): a game asks once per body).
  struct Fill {
    ValidSet shape;
    Box64 box;
  };
  std::vector<Fill> fills_;
  // Per update (storage reused).
  // replace_cells splits the replaced cells into those traced before this update and those
  // scanned in it.
  std::vector<Box64> replaced_, fresh_, traced_before_, scanned_now_;
  // Since the chains were last traced (trace_surface): the cells gone, as they were then, and
  // the boxes of the records scanned since (ascending).
  std::vector<GoneCell> gone_;
  std::vector<Box64> untraced_;
  // follow: the boxes and waits of the jobs the change dropped (their islands altered).
  std::vector<std::pair<Box64, std::size_t>> dropped_;
  std::uint64_t scans_before_ = 0, passes_before_ = 0;
  // What the game holds: the landscape of the last update delivered (its meshes and polygons)
  // and the chains it was given, one bit per chain id (ids only grow, and a bit is set or
  // cleared without allocating, so update_lost() can undo the last delivery). Kept so that a
  // state an update failed in can be rebuilt.
  bool broken_ = false;
  // What stopped it (the exception's message, or the lost update), cut to fit: noting it must
  // not allocate, as it runs when memory ran out.
  std::array<char, 160> broken_by_{};
  Landscape delivered_, delivered_before_;
  std::vector<std::uint64_t> delivered_chains_;     // bit id % 64 of word id / 64
  std::vector<ChainId> last_added_, last_removed_;  // the last delivery's chains
  bool last_delivery_ = false;                      // the two lists describe it
  void hold_chain(ChainId id, bool held) noexcept;
  std::vector<ChainId> held_chains() const;
  void make_room_for(ChainId id);
};

}  // namespace edgeland::game_detail
