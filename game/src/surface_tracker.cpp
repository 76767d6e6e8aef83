// SurfaceTracker (surface_tracker.hpp): an edit's cells get new chains; the cells touching them
// are computed again and replaced where they differ; the cells touching those get their ghosts
// checked.
#include "edgeland/game/surface_tracker.hpp"

#include <algorithm>
#include <set>

#include "cell_polygons.hpp"
#include "cell_surface.hpp"
#include "ghosts.hpp"

namespace edgeland {
namespace {

using game_detail::CellSurface;

bool interiors_meet(const Box64& a, const Box64& b) {
  return a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y;
}

// The cells of `world` whose closed box meets one of `boxes` and is not one of `except`.
template <class Set>
Set touching(const Landscape& world, const Set& boxes, const Set& except) {
  Set out;
  for (const Box64& b : boxes)
    world.cells_in(b, [&](const CellView& c) {
      if (!except.count(c.box) && !boxes.count(c.box)) out.insert(c.box);
      return true;
    });
  return out;
}

bool holds_an_end(const SurfaceChain& c, const Box64& box) {
  return box.contains(c.points.front()) || box.contains(c.points.back());
}

}  // namespace

bool SurfaceTracker::BoxLess::operator()(const Box64& l, const Box64& r) const noexcept {
  if (l.min != r.min) return l.min < r.min;
  return l.max < r.max;
}

SurfaceTracker::SurfaceTracker(const Landscape& world, const SurfaceOptions& options)
    : options_(options), seen_(world) {
  replace_cells(world, {}, game_detail::all_cells(world));
}

ChainId SurfaceTracker::keep(const SurfaceChain& chain, ChainUpdate& update) {
  const ChainId id = next_id_++;
  chains_.emplace(id, chain);
  update.added.emplace_back(id, chain);
  return id;
}

ChainUpdate SurfaceTracker::update(const Landscape& world, const ChangeSet& changes) {
  std::vector<Box64> gone;
  for (const Box64& box : changes.cells)
    seen_.cells_in(box, [&](const CellView& c) {
      if (interiors_meet(c.box, box)) gone.push_back(c.box);
      return true;
    });
  return replace_cells(world, gone, changes.cells);
}

ChainUpdate SurfaceTracker::resync(const Landscape& world) {
  std::vector<Box64> gone, fresh;
  std::set<Box64, BoxLess> present;
  world.cells_in(world.world(), [&](const CellView& c) {
    present.insert(c.box);
    std::vector<PolygonId> ids;
    world.polygons_in(c.box, [&](const PolygonView& v) {
      if (v.cell == c.box) ids.push_back(v.id);
      return true;
    });
    const auto it = cells_.find(c.box);
    if (it == cells_.end() || it->second.ids != ids) fresh.push_back(c.box);
    if (it != cells_.end() && it->second.ids != ids) gone.push_back(c.box);
    return true;
  });
  for (const auto& [box, record] : cells_)
    if (!present.count(box)) gone.push_back(box);
  return replace_cells(world, gone, fresh);
}

ChainUpdate SurfaceTracker::replace_cells(const Landscape& world, const std::vector<Box64>& gone,
                                          const std::vector<Box64>& fresh) {
  using BoxSet = std::set<Box64, BoxLess>;
  ChainUpdate update;
  for (const Box64& box : gone) {
    const auto it = cells_.find(box);
    if (it == cells_.end()) continue;
    for (ChainId id : it->second.chains) {
      update.removed.push_back(id);
      chains_.erase(id);
    }
    cells_.erase(it);
  }
  const BoxSet changed(fresh.begin(), fresh.end());
  const BoxSet near = touching(world, changed, BoxSet{});
  // Stages 1-3 for the changed cells and their neighbours.
  std::map<Box64, CellSurface, BoxLess> computed;
  for (const BoxSet* set : {&changed, &near})
    for (const Box64& box : *set) computed.emplace(box, game_detail::cell_surface(world, box, options_));
  // Chains around a point: the new ones where computed, the kept ones elsewhere.
  const game_detail::ChainsAround around = [&](Point64 p, std::vector<const SurfaceChain*>& out) {
    for (const Box64& box : game_detail::cells_at(world, p)) {
      if (const auto it = computed.find(box); it != computed.end()) {
        for (const SurfaceChain& c : it->second.chains) out.push_back(&c);
      } else if (const auto kept = cells_.find(box); kept != cells_.end()) {
        for (ChainId id : kept->second.chains) out.push_back(&chains_.at(id));
      }
    }
  };
  const Box64& w = world.world();
  for (auto& [box, surface] : computed)
    for (SurfaceChain& c : surface.chains) game_detail::set_ghosts(c, around, w, options_.border_wall);
  // Chains of the cells beyond: the same points, but a ghost may point into a changed cell.
  BoxSet inner = changed;
  inner.insert(near.begin(), near.end());
  std::vector<std::pair<ChainId, SurfaceChain>> reghosted;
  for (const Box64& box : touching(world, near, changed)) {
    const auto it = cells_.find(box);
    if (it == cells_.end()) continue;
    for (ChainId id : it->second.chains) {
      SurfaceChain c = chains_.at(id);
      if (c.closed || std::none_of(inner.begin(), inner.end(),
                                   [&](const Box64& b) { return holds_an_end(c, b); }))
        continue;
      game_detail::set_ghosts(c, around, w, options_.border_wall);
      if (!(c == chains_.at(id))) reghosted.emplace_back(id, std::move(c));
    }
  }
  // Commit: the changed cells' chains are all new; a neighbour keeps every chain it had.
  for (auto& [box, surface] : computed) {
    CellRecord& record = cells_[box];
    std::vector<ChainId> before = std::move(record.chains);
    record = {surface.ids, {}};
    for (const SurfaceChain& c : surface.chains) {
      const auto same = std::find_if(before.begin(), before.end(),
                                     [&](ChainId id) { return chains_.at(id) == c; });
      if (same != before.end()) {
        record.chains.push_back(*same);
        before.erase(same);
      } else {
        record.chains.push_back(keep(c, update));
      }
    }
    for (ChainId id : before) {
      update.removed.push_back(id);
      chains_.erase(id);
    }
  }
  for (auto& [id, chain] : reghosted) {
    update.removed.push_back(id);
    std::vector<ChainId>& ids = cells_.at(chain.cell).chains;
    const ChainId fresh_id = keep(chain, update);
    std::replace(ids.begin(), ids.end(), id, fresh_id);
    chains_.erase(id);
  }
  std::sort(update.removed.begin(), update.removed.end());
  seen_ = world;
  return update;
}

}  // namespace edgeland
