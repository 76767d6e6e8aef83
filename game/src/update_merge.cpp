#include "update_merge.hpp"

#include <algorithm>

#include "cell_store.hpp"

namespace edgeland::game_detail {
namespace {

// Removes `id` from `added` (ascending by id) if it is there.
template <class Added, class IdOf>
bool cancel(std::vector<Added>& added, std::uint64_t id, IdOf id_of) {
  const auto at = std::lower_bound(added.begin(), added.end(), id,
                                   [&](const Added& a, std::uint64_t i) { return id_of(a) < i; });
  if (at == added.end() || id_of(*at) != id) return false;
  added.erase(at);
  return true;
}

void add_delta(ChangeSet& into, Material m, Int128 delta) {
  for (auto& [material, sum] : into.twice_area_delta)
    if (material == m) {
      sum += delta;
      return;
    }
  into.twice_area_delta.emplace_back(m, delta);
}

}  // namespace

void take_changes(ChangeSet& into, ChangeSet&& more) {
  const auto id_of = [](const ChangeSet::Added& a) { return a.id; };
  for (PolygonId id : more.removed)
    if (!cancel(into.added, id, id_of)) into.removed.push_back(id);
  for (ChangeSet::Added& a : more.added) into.added.push_back(std::move(a));
  into.cells.insert(into.cells.end(), more.cells.begin(), more.cells.end());
  for (const auto& [m, delta] : more.twice_area_delta) add_delta(into, m, delta);
}

void take_chains(ChainUpdate& into, ChainUpdate&& more) {
  const auto id_of = [](const std::pair<ChainId, SurfaceChain>& a) { return a.first; };
  for (ChainId id : more.removed)
    if (!cancel(into.added, id, id_of)) into.removed.push_back(id);
  for (auto& a : more.added) into.added.push_back(std::move(a));
}

void finish_changes(ChangeSet& changes, const Landscape& world) {
  std::sort(changes.removed.begin(), changes.removed.end());
  std::vector<Box64>& cells = changes.cells;
  std::sort(cells.begin(), cells.end(), box_less);
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  std::erase_if(cells, [&](const Box64& b) { return !world.cell(b).has_value(); });
  std::sort(changes.twice_area_delta.begin(), changes.twice_area_delta.end(),
            [](const auto& l, const auto& r) { return l.first < r.first; });
}

void finish_chains(ChainUpdate& chains) { std::sort(chains.removed.begin(), chains.removed.end()); }

}  // namespace edgeland::game_detail
