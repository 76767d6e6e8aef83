#pragma once
// The storage of ChainEndIndex (ghosts.hpp): a multimap from points to chains in one flat array.
// It was an unordered_map of vectors, a heap node and a heap vector per end point; the surface
// update's stages that read and write it (unindex, ghosts, reghost, commit) were memory-bound,
// each lookup a chase through two allocations. Here a lookup reads one short run of adjacent
// slots and nothing is allocated once the table has reached its size.
//
// Invariants:
//  - open addressing, linear probing from Point64Hash (not std::hash: the same on every
//    platform), a power-of-two capacity;
//  - live entries plus tombstones (slots of erased entries that a probe must step over) fill at
//    most half the slots; an insert that would pass that rehashes: in place when tombstones were
//    the excess, else at twice the size (the table never shrinks);
//  - an erased entry whose successor slot is empty becomes empty itself (with the tombstones just
//    before it), so runs do not fill with tombstones under steady churn;
//  - a rehash keeps the old slots for the next one: no allocation once the table has its size;
//  - every entry carries the sequence number of its insertion, and `replace` keeps it: `append`
//    hands out a point's chains in insertion order, whatever their slots. That order is the
//    index's contract (the order in which a surface update re-keys kept chains, so chain ids).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/game/game_types.hpp"

namespace edgeland::game_detail {

class ChainEndTable {
 public:
  // A new entry (p, chain), after every entry already at p in `append`'s order.
  void insert(Point64 p, const SurfaceChain* chain);
  // Erases every entry (p, chain); none is a no-op.
  void erase(Point64 p, const SurfaceChain* chain);
  // Every entry (p, from) holds `to` instead, in its place in the order.
  void replace(Point64 p, const SurfaceChain* from, const SurfaceChain* to);
  // Appends the chains of the entries at p, in insertion order.
  void append(Point64 p, std::vector<const SurfaceChain*>& out) const;

  std::size_t size() const noexcept { return live_; }
  std::size_t capacity() const noexcept { return slots_.size(); }
  std::size_t tombstones() const noexcept { return used_ - live_; }

 private:
  // Sequence numbers of live entries start at kFirstSeq; the two below mark free slots.
  static constexpr std::uint64_t kEmpty = 0, kTombstone = 1, kFirstSeq = 2;
  struct Entry {
    Point64 point;
    const SurfaceChain* chain = nullptr;
    std::uint64_t seq = kEmpty;
    bool live() const noexcept { return seq >= kFirstSeq; }
  };
  // A matching entry found by `append`, sorted by seq before it is handed out.
  struct Match {
    std::uint64_t seq;
    const SurfaceChain* chain;
  };

  std::size_t home(Point64 p) const noexcept;
  std::size_t next(std::size_t i) const noexcept { return (i + 1) & (slots_.size() - 1); }
  bool holds(const Entry& e, Point64 p) const noexcept { return e.live() && e.point == p; }
  void make_room();
  void rehash(std::size_t capacity);
  void place(const Entry& e);
  void free_slot(std::size_t i);

  std::vector<Entry> slots_;
  std::vector<Entry> spare_;  // the slots before the last rehash, reused by the next one
  std::size_t live_ = 0;      // live entries
  std::size_t used_ = 0;      // live entries and tombstones
  std::uint64_t next_seq_ = kFirstSeq;
  mutable std::vector<Match> matches_;  // append's scratch, kept to stay allocation-free
};

}  // namespace edgeland::game_detail
