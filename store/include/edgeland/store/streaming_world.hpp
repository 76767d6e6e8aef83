#pragma once
// A landscape bigger than memory (store/README.md, "StreamingWorld"): its regions live in a
// region store and are loaded when an edit reaches them; the least recently used are written
// back (when changed) and unloaded whenever the loaded ones pass a budget of bytes.
//
// Edits are numbered 0, 1, ... and every region row carries the number of edits it has seen
// (its sequence number). A world opened again after a crash goes on from the smallest of them,
// and applies each edit only to the regions that have not seen it: every edit reaches every
// region exactly once, so the run ends where an uninterrupted one ends.
#include <cstddef>
#include <cstdint>
#include <list>
#include <map>

#include "edgeland/store/region_store.hpp"

namespace edgeland::store {

class EDGELAND_EXPORT StreamingWorld {
 public:
  // Opens the world the store holds, every region unloaded, at the first edit some region has
  // not seen. `budget`: the bytes the loaded regions may take (Landscape::region_bytes) once an
  // edit is done; it must hold the regions of the largest edit. Throws what open_world throws.
  StreamingWorld(RegionStore& store, std::size_t budget, const LandscapeLimits& limits = {});

  // Applies edit number sequence(): loads the regions its shape reaches that have not seen it,
  // applies it to them (apply_edit; regions that have seen it stay unloaded and are skipped),
  // marks the ones it changed, and evicts down to the budget. The edit's errors leave the world
  // as it was (the regions it loaded stay loaded). Throws StoreError or LoadError from the
  // store too.
  ChangeSet apply(const Edit& edit);
  // Writes every changed region and the world's row in one transaction.
  void flush();

  const Landscape& world() const noexcept { return world_; }
  // The number of the next edit.
  std::uint64_t sequence() const noexcept { return seq_; }

  struct Stats {
    std::size_t loads = 0, evictions = 0, writes = 0, commits = 0;
    std::size_t loaded_bytes = 0, peak_loaded_bytes = 0;  // after each edit's evictions
  };
  const Stats& stats() const noexcept { return stats_; }

 private:
  struct Loaded {
    std::size_t bytes = 0;
    bool dirty = false;
    std::list<TreePath>::iterator at;  // in lru_
  };
  void bring_in(const std::vector<TreePath>& paths);
  void evict_to_budget();
  WorldRecord record() const;

  RegionStore& store_;
  std::size_t budget_;
  std::map<TreePath, std::uint64_t> seen_;  // every region: the edits it has seen (before world_,
                                            // which the constructor opens while filling it)
  Landscape world_;
  std::uint64_t seq_ = 0;
  std::list<TreePath> lru_;  // least recently used first
  std::map<TreePath, Loaded> loaded_;
  Stats stats_;
};

}  // namespace edgeland::store
