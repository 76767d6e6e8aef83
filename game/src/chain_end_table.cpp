#include "chain_end_table.hpp"

#include <algorithm>

namespace edgeland::game_detail {
namespace {

// The smallest table: a few chains need no rehash at all.
constexpr std::size_t kMinCapacity = 16;

}  // namespace

void ChainEndTable::insert(Point64 p, const SurfaceChain* chain) {
  make_room();
  place({p, chain, next_seq_++});
}

void ChainEndTable::erase(Point64 p, const SurfaceChain* chain) {
  if (live_ == 0) return;
  for (std::size_t i = home(p); slots_[i].seq != kEmpty; i = next(i))
    if (holds(slots_[i], p) && slots_[i].chain == chain) free_slot(i);
}

void ChainEndTable::replace(Point64 p, const SurfaceChain* from, const SurfaceChain* to) {
  if (live_ == 0) return;
  for (std::size_t i = home(p); slots_[i].seq != kEmpty; i = next(i))
    if (holds(slots_[i], p) && slots_[i].chain == from) slots_[i].chain = to;
}

// The matches are few (the chains ending at one point): sorting them is cheap, and it makes the
// order independent of where probing and rehashing put the entries.
void ChainEndTable::append(Point64 p, std::vector<const SurfaceChain*>& out) const {
  if (live_ == 0) return;
  matches_.clear();
  for (std::size_t i = home(p); slots_[i].seq != kEmpty; i = next(i))
    if (holds(slots_[i], p)) matches_.push_back({slots_[i].seq, slots_[i].chain});
  std::sort(matches_.begin(), matches_.end(),
            [](const Match& a, const Match& b) { return a.seq < b.seq; });
  for (const Match& m : matches_) out.push_back(m.chain);
}

std::size_t ChainEndTable::home(Point64 p) const noexcept {
  return Point64Hash{}(p) & (slots_.size() - 1);
}

// Keeps live entries and tombstones at most half the slots after one more insert. A rehash
// leaves the live ones at most a quarter, so at least a quarter of the slots are inserted into
// before the next one: inserts stay amortised constant time however the erases fall.
void ChainEndTable::make_room() {
  if (2 * (used_ + 1) <= slots_.size()) return;
  std::size_t capacity = std::max(kMinCapacity, slots_.size());
  while (4 * live_ > capacity) capacity *= 2;
  rehash(capacity);
}

// The old slots are kept as the next rehash's storage: a game's steady churn rehashes in place
// again and again, and would otherwise allocate and free the whole table each time.
void ChainEndTable::rehash(std::size_t capacity) {
  spare_.assign(capacity, Entry{});
  spare_.swap(slots_);
  live_ = used_ = 0;
  for (const Entry& e : spare_)
    if (e.live()) place(e);
}

// Into the first free slot of p's run; the sequence number comes with the entry.
void ChainEndTable::place(const Entry& e) {
  std::size_t i = home(e.point);
  while (slots_[i].live()) i = next(i);
  if (slots_[i].seq == kEmpty) ++used_;
  slots_[i] = e;
  ++live_;
}

// A tombstone, unless the run ends right after slot i: then no probe needs to step over it, nor
// over the tombstones just before it, and they all become empty.
void ChainEndTable::free_slot(std::size_t i) {
  --live_;
  slots_[i].seq = kTombstone;
  if (slots_[next(i)].seq != kEmpty) return;
  const std::size_t mask = slots_.size() - 1;
  for (; slots_[i].seq == kTombstone; i = (i - 1) & mask) {
    slots_[i].seq = kEmpty;
    --used_;
  }
}

}  // namespace edgeland::game_detail
