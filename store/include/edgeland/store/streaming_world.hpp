#pragma once
// A landscape bigger than memory (store/README.md, "StreamingWorld"): its regions live in a
// region store and are loaded when an edit reaches them; the least recently used are written
// back (when changed) and unloaded whenever the loaded ones pass a budget of bytes.
#include <cstddef>
#include <cstdint>
#include <list>
#include <map>

#include "edgeland/store/region_store.hpp"

namespace edgeland::store {

class EDGELAND_EXPORT StreamingWorld {
 public:
  // Opens the world the store holds, every region unloaded. `budget`: the bytes the loaded
  // regions may take (Landscape::region_bytes) once an edit is done; it must hold the regions
  // of the largest edit. Throws what open_world throws.
  StreamingWorld(RegionStore& store, std::size_t budget, const LandscapeLimits& limits = {});

  // Loads the regions the edit's shape reaches, applies it (apply_edit), marks the regions it
  // changed, and evicts down to the budget. The edit's errors leave the world as it was (the
  // regions it loaded stay loaded). Throws StoreError or LoadError from the store too.
  ChangeSet apply(const Edit& edit);
  // Writes every changed region and the world's row in one transaction.
  void flush();

  const Landscape& world() const noexcept { return world_; }
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
  Landscape world_;
  std::uint64_t seq_ = 0;
  std::list<TreePath> lru_;  // least recently used first
  std::map<TreePath, Loaded> loaded_;
  Stats stats_;
};

}  // namespace edgeland::store
