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
  GameState(Landscape world, const GameOptions& options);

  GameUpdate apply(std::span<const Edit> edits);
  GameUpdate reset(Landscape world);
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
  void replace_cells(std::span<const Box64> replaced, std::span<const Box64> fresh,
                     GameUpdate& out);
  void drain_debris(GameUpdate& out);
  std::vector<DebrisJob> advance_jobs();
  DebrisJob::Pace pace_of(const Waiting& w) const;
  void queue_islands(std::vector<Island> islands);
  void finish(GameUpdate& out) const;
  void note_fills(std::span<const Edit> edits);
  void start_work();

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
  std::vector<Box64> replaced_, fresh_;
  std::vector<GoneCell> gone_;
  std::uint64_t scans_before_ = 0, passes_before_ = 0;
};

}  // namespace edgeland::game_detail
