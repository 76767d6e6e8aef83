#pragma once
// The chains of every cell kept in step with a landscape (game/README.md, "Keeping chains in
// step"), from the cell records of a CellStore. An update takes the cells a change replaced
// (gone) and the new ones (fresh, already scanned into the store) and hands back the chains to
// remove and to add. Its stages:
//
//   covers     the fresh cells' covers from their neighbours' port spans; the neighbours across
//              a side whose spans changed get theirs again, and join the computed cells where
//              they differ (their own polygons did not change: only their covers can);
//   trace      stages 2-3 for every computed cell, from its record: no polygon is read;
//   unindex    the old chains of the computed cells leave the end index;
//   ghosts     the new chains enter it and take their ghosts; a kept chain with an end where a
//              chain left or entered takes its ghosts again (a ghost depends only on the chains
//              with an end at the chain's ends);
//   commit     a new chain equal to an old one of the same box (ghosts included) keeps its id,
//              every other one takes a fresh id; the old ones left are removed.
//
// Applying the updates to a mirror gives exactly surface_chains() after every change.
#include <map>
#include <span>
#include <unordered_map>
#include <vector>

#include "cell_store.hpp"
#include "chain_tracing.hpp"
#include "ghosts.hpp"
#include "surface_segments.hpp"

namespace edgeland::game_detail {

class SurfaceState {
 public:
  // Chain ids start at `first_id` (a driver rebuilt after a failure continues its old ids:
  // ids a game was told are removed never come back).
  explicit SurfaceState(const SurfaceOptions& options, ChainId first_id = 1)
      : options_(options), next_id_(first_id) {}
  SurfaceState(const SurfaceState&) = delete;
  SurfaceState& operator=(const SurfaceState&) = delete;

  // `world` after a change that replaced the cells `gone` (taken out of `store`) by `fresh`
  // (scanned into it). Every cell of `world` has a record in `store`.
  ChainUpdate update(const Landscape& world, CellStore& store, std::span<const GoneCell> gone,
                     std::span<const Box64> fresh);

  const std::map<ChainId, SurfaceChain>& chains() const noexcept { return chains_; }
  const SurfaceOptions& options() const noexcept { return options_; }
  ChainId next_id() const noexcept { return next_id_; }
  // The cells traced again by the last update (fresh ones and neighbours whose covers changed).
  std::size_t last_traced() const noexcept { return computed_.size(); }

 private:
  // A cell whose chains are traced again, and its new chains (ghosts set in stage "ghosts").
  struct Computed {
    Box64 box;
    std::vector<ChainId> old;          // its chains before (the gone cell's of that box, if any)
    std::size_t first = 0, count = 0;  // its new chains in pending_
  };

  void compute_covers(const Landscape& world, CellStore& store, std::span<const Box64> fresh);
  void recover_neighbours(const Landscape& world, CellStore& store, const Box64& box,
                          std::span<const Box64> around);
  void add_computed(CellRecord& record, const Box64& box, std::vector<ChainId> old);
  bool covers_changed(const Landscape& world, CellStore& store, const Box64& box);
  void covers_of(const Landscape& world, const CellStore& store, const Box64& box, SideSpans& out);
  void trace(const Landscape& world, const CellStore& store);
  void unindex(const CellStore& store, std::span<const GoneCell> gone);
  void set_ghosts(const Box64& world);
  void reghost_kept(const Box64& world, CellStore& store, ChainUpdate& update);
  void rekey(const SurfaceChain& kept, const Ghosts& again, CellStore& store, ChainUpdate& update);
  void commit(CellStore& store, std::span<const GoneCell> gone, ChainUpdate& update);
  using OldChain = std::pair<ChainId, std::map<ChainId, SurfaceChain>::iterator>;
  ChainId take(SurfaceChain& chain, ChainUpdate& update);
  void remove(std::map<ChainId, SurfaceChain>::iterator at, ChainUpdate& update);
  std::map<ChainId, SurfaceChain>::iterator held(ChainId id);
  bool traced_now(const CellStore& store, const Box64& box) const;

  SurfaceOptions options_;
  std::map<ChainId, SurfaceChain> chains_;
  ChainEndIndex ends_;
  ChainId next_id_ = 1;
  // Per update (storage reused).
  std::vector<Computed> computed_;
  std::vector<SurfaceChain> pending_;
  std::vector<Point64> affected_;  // ends of chains that left or entered the index
  std::vector<NeighbourSpans> neighbours_;
  // compute_covers: the cells touching fresh cell k are around_fresh_[around_begin_[k] ..
  // around_begin_[k + 1]).
  std::vector<Box64> around_fresh_;
  std::vector<std::size_t> around_begin_;
  std::vector<SurfaceSegment> segments_;
  std::vector<TracedChain> traced_;
  TraceScratch trace_scratch_;
  SideSpans covers_;
  std::vector<const SurfaceChain*> around_;
  std::vector<OldChain> old_;  // commit: the old chains of the cell being committed
  std::unordered_map<Box64, const GoneCell*, BoxHash> gone_;
  std::uint64_t stamp_ = 0;  // this update's number (CellRecord::traced_in)
};

}  // namespace edgeland::game_detail
