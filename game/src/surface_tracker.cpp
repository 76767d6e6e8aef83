// SurfaceTracker (surface_tracker.hpp): an edit's cells get new chains; the cells touching them
// are computed again and replaced where they differ; the cells touching those get their ghosts
// checked.
#include "edgeland/game/surface_tracker.hpp"

#include <algorithm>
#include <optional>
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

// A cell's covers from the ports of the cells across its sides: a changed cell's new ones
// (`new_ports`), the others' kept in their records; nothing when such a cell has neither (never
// after an update that saw every change: the caller then reads the polygons).
template <class NewPorts, class Records>
std::optional<game_detail::SideSpans> covers_around(const Landscape& world, const Box64& box,
                                                    const NewPorts& new_ports,
                                                    const Records& records) {
  std::vector<game_detail::NeighbourPorts> neighbours;
  bool complete = true;
  world.cells_in(box, [&](const CellView& c) {
    const bool overlaps_x = c.box.max.x > box.min.x && c.box.min.x < box.max.x;
    const bool overlaps_y = c.box.max.y > box.min.y && c.box.min.y < box.max.y;
    if (c.box == box || !(overlaps_x || overlaps_y)) return true;  // itself, or at a corner
    if (const auto it = new_ports.find(c.box); it != new_ports.end())
      neighbours.push_back({c.box, it->second});
    else if (const auto rec = records.find(c.box); rec != records.end())
      neighbours.push_back({c.box, rec->second.ports});
    else
      complete = false;
    return complete;
  });
  if (!complete) return std::nullopt;
  return game_detail::covers_from_ports(box, neighbours);
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
  // The old cells under the edit: their chains wait for the commit, where a new cell with the
  // same box keeps those it has unchanged (most chains of a cell lie away from the edit), so an
  // engine replaces only what changed.
  std::map<Box64, std::vector<ChainId>, BoxLess> orphans;
  std::map<Box64, std::vector<std::int64_t>, BoxLess> old_ports;
  for (const Box64& box : gone) {
    const auto it = cells_.find(box);
    if (it == cells_.end()) continue;
    orphans[box] = std::move(it->second.chains);
    old_ports[box] = std::move(it->second.ports);
    cells_.erase(it);
  }
  const BoxSet changed(fresh.begin(), fresh.end());
  const Box64& w = world.world();
  // Stages 1-3 for the changed cells, and for the neighbours whose covers changed: a neighbour's
  // own polygons are as they were (the edit did not touch it), so with the same covers from
  // across its sides its chains are the same points (a ghost may still move: below).
  std::map<Box64, CellSurface, BoxLess> computed;
  for (const Box64& box : changed)
    computed.emplace(box, game_detail::cell_surface(world, box, options_));
  // A neighbour's covers are the ports of the cells across its sides: when the edit re-cut its
  // cells in place (the same boxes) and left their ports as they were, no neighbour can see it.
  std::map<Box64, std::vector<std::int64_t>, BoxLess> new_ports;
  for (const auto& [box, surface] : computed)
    new_ports.emplace(box, game_detail::flatten(surface.ports));
  const bool seen_from_outside = old_ports.size() != changed.size() ||
                                 !std::equal(new_ports.begin(), new_ports.end(), old_ports.begin());
  // A neighbour's covers come from the ports of the cells around it (the changed ones' new
  // ports, the others' kept ones), so one whose covers stayed is never read; its own polygons
  // are those it had (the change set names every cell the edit replaced).
  for (const Box64& box : seen_from_outside ? touching(world, changed, BoxSet{}) : BoxSet{}) {
    std::optional<game_detail::SideSpans> covers = covers_around(world, box, new_ports, cells_);
    const auto it = cells_.find(box);
    if (covers && it != cells_.end() && it->second.covers == game_detail::flatten(*covers))
      continue;
    game_detail::CellPolygons polygons = game_detail::read_cell(world, box);
    if (!covers) covers = game_detail::side_covers(polygons, options_.materials);
    computed.emplace(box, game_detail::cell_surface(polygons, std::move(*covers), w, options_));
  }
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
  for (auto& [box, surface] : computed)
    for (SurfaceChain& c : surface.chains)
      game_detail::set_ghosts(c, around, w, options_.border_wall);
  // Chains kept around the computed cells: the same points, but a ghost taken at an end in a
  // computed cell's closed box may have moved.
  BoxSet inner;
  for (const auto& [box, surface] : computed) inner.insert(box);
  std::vector<std::pair<ChainId, SurfaceChain>> reghosted;
  for (const Box64& box : touching(world, inner, inner)) {
    const auto it = cells_.find(box);
    if (it == cells_.end()) continue;
    for (ChainId id : it->second.chains) {
      const SurfaceChain& kept = chains_.at(id);
      if (kept.closed || std::none_of(inner.begin(), inner.end(),
                                      [&](const Box64& b) { return holds_an_end(kept, b); }))
        continue;
      SurfaceChain c = kept;
      game_detail::set_ghosts(c, around, w, options_.border_wall);
      if (!(c == kept)) reghosted.emplace_back(id, std::move(c));
    }
  }
  // Commit: every computed cell keeps the chains it had (a neighbour) or its old cell of the same
  // box had (a changed cell) where they are equal, ghosts included; the others are new.
  for (auto& [box, surface] : computed) {
    CellRecord& record = cells_[box];
    std::vector<ChainId> before = std::move(record.chains);
    if (const auto o = orphans.find(box); o != orphans.end()) {
      before.insert(before.end(), o->second.begin(), o->second.end());
      orphans.erase(o);
    }
    record = {
        surface.ids, {}, game_detail::flatten(surface.covers), game_detail::flatten(surface.ports)};
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
  for (const auto& [box, ids] : orphans)  // cells split or merged away
    for (ChainId id : ids) {
      update.removed.push_back(id);
      chains_.erase(id);
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
