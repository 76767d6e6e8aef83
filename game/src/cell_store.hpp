#pragma once
// What a game-layer owner keeps of every cell of the landscape (game_state.hpp): the cell's scan
// (stage 1, read once when the cell is new) and what its chains read and are. The chains
// (surface_state.hpp) and the island summaries (island_tree.hpp) of a changed cell and of its
// neighbours are derived from these records alone: a cell's polygons are read once, when it is
// scanned.
#include <span>
#include <unordered_map>
#include <vector>

#include "cell_scan.hpp"
#include "edgeland/game/game_types.hpp"

namespace edgeland::game_detail {

struct BoxHash {
  std::size_t operator()(const Box64& b) const noexcept {
    return Point64Hash{}(b.min) * 31u ^ Point64Hash {}(b.max);
  }
};

struct CellRecord {
  CellScan scan;
  SideSpans covers;             // where the neighbours' solid lies across its sides
  std::vector<ChainId> chains;  // its chains (surface_state.hpp), in the order traced
  std::uint64_t traced_in = 0;  // the surface update that last traced it
};

// A cell the landscape no longer has as it was: what the chains need of it.
struct GoneCell {
  Box64 box;
  std::vector<ChainId> chains;
  SideSpans port_spans;
  std::optional<CellContents> contents;  // its polygons
};

class CellStore {
 public:
  // Takes out the records of the boxes that have one, appending what is left of them to `gone`.
  void remove(std::span<const Box64> boxes, std::vector<GoneCell>& gone);
  // Takes out the records of the boxes that have one, keeping nothing of them.
  void drop(std::span<const Box64> boxes);
  // Scans the cells of `world` with these boxes into new records (replacing any).
  void scan(const Landscape& world, std::span<const Box64> boxes,
            const PhysicsMaterials& materials);

  CellRecord* find(const Box64& box);
  const CellRecord* find(const Box64& box) const;
  CellRecord& at(const Box64& box);
  const CellRecord& at(const Box64& box) const;
  std::size_t size() const { return cells_.size(); }
  // How many cells were scanned since the store was made.
  std::uint64_t scans() const { return scans_; }

  template <class F>
  void for_each(F&& f) const {
    for (const auto& [box, record] : cells_) f(box, record);
  }

 private:
  using Cells = std::unordered_map<Box64, CellRecord, BoxHash>;
  void retire(Cells::iterator it);
  Cells cells_;
  std::vector<CellRecord> spare_;  // records taken out: their storage goes to the next scans
  ScanScratch scratch_;
  std::uint64_t scans_ = 0;
};

// The cells of `before` a change replaced: those whose interiors meet a new cell's (`fresh`,
// ChangeSet::cells).
void replaced_cells(const Landscape& before, std::span<const Box64> fresh, std::vector<Box64>& out);

// The order cell boxes are kept in (lists of cells searched by binary search, a change set's
// cells): by min corner, then max corner.
inline bool box_less(const Box64& l, const Box64& r) {
  return l.min != r.min ? l.min < r.min : l.max < r.max;
}

// The cells of `world` whose polygons differ from the store's records (`fresh`), and the
// records that no longer match a cell of `world` as it is (`gone`): a change of any kind (a
// snapshot restored, a load) as a replacement of cells. O(N).
void differing_cells(const Landscape& world, const CellStore& store, std::vector<Box64>& gone,
                     std::vector<Box64>& fresh);

}  // namespace edgeland::game_detail
