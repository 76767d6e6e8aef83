#include "cell_store.hpp"

#include <algorithm>

namespace edgeland::game_detail {
namespace {

// Whether a record still describes the cell: the same polygons with the same ids and materials
// (ids alone could repeat in another landscape, a load).
bool same_cell(const CellScan& kept, const CellContents& now) {
  // std::equal, not std::ranges::equal: Emscripten 3.1.6's libc++ has no ranges algorithms.
  const auto same = [](auto a, auto b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  };
  if (!same(kept.ids(), now.ids())) return false;
  if (!same(kept.contents->polygons(), now.polygons())) return false;
  for (std::size_t i = 0; i < now.size(); ++i)
    if (kept.materials[i] != now.material(i)) return false;
  return true;
}

}  // namespace

void CellStore::remove(std::span<const Box64> boxes, std::vector<GoneCell>& gone) {
  for (const Box64& box : boxes) {
    const auto it = cells_.find(box);
    if (it == cells_.end()) continue;
    CellRecord& r = it->second;
    gone.push_back({box, std::move(r.chains), r.scan.port_spans, std::move(r.scan.contents)});
    retire(it);
  }
}

void CellStore::drop(std::span<const Box64> boxes) {
  for (const Box64& box : boxes)
    if (const auto it = cells_.find(box); it != cells_.end()) retire(it);
}

// The record's storage is kept for the next scan; the old cell's polygons are not kept alive by
// a spare record.
void CellStore::retire(Cells::iterator it) {
  CellRecord& r = it->second;
  r.chains.clear();
  r.scan.contents.reset();
  spare_.push_back(std::move(r));
  cells_.erase(it);
}

void CellStore::scan(const Landscape& world, std::span<const Box64> boxes,
                     const PhysicsMaterials& materials) {
  for (const Box64& box : boxes) {
    CellRecord record;
    if (!spare_.empty()) {
      record = std::move(spare_.back());
      spare_.pop_back();
    }
    scan_cell(world.cell(box).value(), world.world(), materials, record.scan, scratch_);
    record.chains.clear();
    ++scans_;
    cells_.insert_or_assign(box, std::move(record));
  }
}

CellRecord* CellStore::find(const Box64& box) {
  const auto it = cells_.find(box);
  return it == cells_.end() ? nullptr : &it->second;
}

const CellRecord* CellStore::find(const Box64& box) const {
  const auto it = cells_.find(box);
  return it == cells_.end() ? nullptr : &it->second;
}

CellRecord& CellStore::at(const Box64& box) { return cells_.at(box); }
const CellRecord& CellStore::at(const Box64& box) const { return cells_.at(box); }

void replaced_cells(const Landscape& before, std::span<const Box64> fresh,
                    std::vector<Box64>& out) {
  out.clear();
  for (const Box64& box : fresh)
    before.cells_in(box, [&](const CellView& c) {
      if (c.box.overlaps_open(box)) out.push_back(c.box);
      return true;
    });
  std::sort(out.begin(), out.end(), box_less);
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

void differing_cells(const Landscape& world, const CellStore& store, std::vector<Box64>& gone,
                     std::vector<Box64>& fresh) {
  gone.clear();
  fresh.clear();
  std::unordered_map<Box64, bool, BoxHash> present;
  world.cells_in(world.world(), [&](const CellView& c) {
    const std::optional<CellContents> now = world.cell(c.box);
    const CellRecord* r = store.find(c.box);
    const bool same = r != nullptr && same_cell(r->scan, *now);
    present.emplace(c.box, same);
    if (!same) fresh.push_back(c.box);
    if (r != nullptr && !same) gone.push_back(c.box);
    return true;
  });
  store.for_each([&](const Box64& box, const CellRecord&) {
    if (!present.count(box)) gone.push_back(box);
  });
  std::sort(gone.begin(), gone.end(), box_less);
}

}  // namespace edgeland::game_detail
