#include "surface_state.hpp"

#include <algorithm>
#include <stdexcept>

namespace edgeland::game_detail {
namespace {

// Whether `other` lies across `side` of `box` along a stretch of positive length.
bool shares_side(const Box64& box, Side side, const Box64& other) {
  if (!across(box, side, other)) return false;
  const bool horizontal = side == Side::kBottom || side == Side::kTop;
  return horizontal ? std::min(box.max.x, other.max.x) > std::max(box.min.x, other.min.x)
                    : std::min(box.max.y, other.max.y) > std::max(box.min.y, other.min.y);
}

void add_ends(const SurfaceChain& c, std::vector<Point64>& out) {
  if (c.closed) return;
  out.push_back(c.points.front());
  out.push_back(c.points.back());
}

}  // namespace

// Whether the cell with this box was traced by this update (a gone cell's box that the
// landscape still has: its old chains are the computed cell's).
bool SurfaceState::traced_now(const CellStore& store, const Box64& box) const {
  const CellRecord* r = store.find(box);
  return r != nullptr && r->traced_in == stamp_;
}

ChainUpdate SurfaceState::update(const Landscape& world, CellStore& store,
                                 std::span<const GoneCell> gone, std::span<const Box64> fresh) {
  ChainUpdate update;
  ++stamp_;
  gone_.clear();
  for (const GoneCell& g : gone) gone_.emplace(g.box, &g);
  compute_covers(world, store, fresh);
  trace(world, store);
  unindex(store, gone);
  set_ghosts(world.world());
  reghost_kept(world.world(), store, update);
  commit(store, gone, update);
  std::sort(update.removed.begin(), update.removed.end());
  return update;
}

// Stage "covers": the fresh cells are computed; a neighbour across a side whose port spans
// changed (every side of a box the landscape did not have before) is computed when its covers
// changed.
void SurfaceState::compute_covers(const Landscape& world, CellStore& store,
                                  std::span<const Box64> fresh) {
  computed_.clear();
  around_fresh_.clear();
  around_begin_.clear();
  for (const Box64& box : fresh) {
    CellRecord& record = store.at(box);
    covers_of(world, store, box, record.covers);
    around_begin_.push_back(around_fresh_.size());
    for (const NeighbourSpans& n : neighbours_) around_fresh_.push_back(n.box);
    const auto before = gone_.find(box);
    add_computed(record, box,
                 before == gone_.end() ? std::vector<ChainId>{} : before->second->chains);
  }
  around_begin_.push_back(around_fresh_.size());
  for (std::size_t k = 0; k < fresh.size(); ++k)
    recover_neighbours(world, store, fresh[k],
                       std::span<const Box64>(around_fresh_)
                           .subspan(around_begin_[k], around_begin_[k + 1] - around_begin_[k]));
}

// The neighbours of a fresh cell (`around`: every cell touching it, in the tree's order) across
// each side whose port spans changed are computed when their covers changed.
void SurfaceState::recover_neighbours(const Landscape& world, CellStore& store, const Box64& box,
                                      std::span<const Box64> around) {
  const auto before = gone_.find(box);
  const SideSpans& now = store.at(box).scan.port_spans;
  for (Side side : kSides) {
    const auto s = static_cast<std::size_t>(side);
    if (before != gone_.end() && before->second->port_spans.sides[s] == now.sides[s]) continue;
    for (const Box64& other : around) {
      if (!shares_side(box, side, other)) continue;
      CellRecord& next = store.at(other);
      if (next.traced_in != stamp_ && covers_changed(world, store, other))
        add_computed(next, other, next.chains);
    }
  }
}

void SurfaceState::add_computed(CellRecord& record, const Box64& box, std::vector<ChainId> old) {
  record.traced_in = stamp_;
  computed_.push_back({box, std::move(old), 0, 0});
}

bool SurfaceState::covers_changed(const Landscape& world, CellStore& store, const Box64& box) {
  covers_of(world, store, box, covers_);
  CellRecord& record = store.at(box);
  if (covers_ == record.covers) return false;
  std::swap(record.covers, covers_);
  return true;
}

void SurfaceState::covers_of(const Landscape& world, const CellStore& store, const Box64& box,
                             SideSpans& out) {
  neighbours_.clear();
  world.cells_in(box, [&](const CellView& c) {
    if (c.box == box) return true;
    const CellRecord* r = store.find(c.box);
    if (r == nullptr) throw std::logic_error("game layer: a cell without a record");
    neighbours_.push_back({c.box, &r->scan.port_spans});
    return true;
  });
  covers_from_ports(box, neighbours_, out);
}

// Stage "trace": stages 2-3 of each computed cell from its record.
void SurfaceState::trace(const Landscape& world, const CellStore& store) {
  pending_.clear();
  for (Computed& c : computed_) {
    const CellRecord& r = *store.find(c.box);
    surface_segments(r.scan, r.covers, world.world(), options_.border_wall, segments_);
    traced_.clear();
    trace_chains(segments_, c.box, world.world(), options_.border_wall, trace_scratch_, traced_);
    c.first = pending_.size();
    c.count = traced_.size();
    for (TracedChain& t : traced_) {
      SurfaceChain chain;
      chain.points = std::move(t.points);
      chain.materials = std::move(t.materials);
      chain.closed = t.closed;
      chain.cell = c.box;
      if (chain.closed) {
        chain.ghost_prev = chain.points.back();
        chain.ghost_next = chain.points.front();
      }
      pending_.push_back(std::move(chain));
    }
  }
}

// Stage "unindex": the chains being replaced leave the end index (the computed cells' old
// chains, and those of gone cells whose box is gone too).
void SurfaceState::unindex(const CellStore& store, std::span<const GoneCell> gone) {
  affected_.clear();
  const auto out = [&](ChainId id) {
    const SurfaceChain& c = chains_.at(id);
    ends_.remove(c);
    add_ends(c, affected_);
  };
  for (const Computed& c : computed_)
    for (ChainId id : c.old) out(id);
  for (const GoneCell& g : gone)
    if (!traced_now(store, g.box))
      for (ChainId id : g.chains) out(id);
}

// Stage "ghosts": the new chains enter the index, then each open one takes its ghosts.
void SurfaceState::set_ghosts(const Box64& world) {
  for (const SurfaceChain& c : pending_) {
    ends_.add(c);
    add_ends(c, affected_);
  }
  const ChainsAround around = ends_.lookup();
  for (SurfaceChain& c : pending_) game_detail::set_ghosts(c, around, world, options_.border_wall);
}

// A kept chain with an end where chains left or entered the index takes its ghosts again; one
// whose ghosts moved is replaced: a new id for the same map node (so the index, which points at
// the node, stays right). A ghost depends only on the chains' points, so the order is free.
void SurfaceState::reghost_kept(const Box64& world, CellStore& store, ChainUpdate& update) {
  std::sort(affected_.begin(), affected_.end());
  affected_.erase(std::unique(affected_.begin(), affected_.end()), affected_.end());
  const ChainsAround around = ends_.lookup();
  const SurfaceChain* pending_begin = pending_.data();
  const SurfaceChain* pending_end = pending_begin + pending_.size();
  for (const Point64 p : affected_) {
    around_.clear();
    ends_.chains_at(p, around_);
    for (const SurfaceChain* kept : around_) {
      if (kept >= pending_begin && kept < pending_end) continue;
      // Only the ghosts can differ (the index holds open chains): no copy of the chain.
      const Ghosts again = ghosts_of(*kept, around, world, options_.border_wall);
      if (again != Ghosts{kept->ghost_prev, kept->ghost_next}) rekey(*kept, again, store, update);
    }
  }
}

void SurfaceState::rekey(const SurfaceChain& kept, const Ghosts& again, CellStore& store,
                         ChainUpdate& update) {
  std::vector<ChainId>& ids = store.at(kept.cell).chains;
  const auto at =
      std::find_if(ids.begin(), ids.end(), [&](ChainId id) { return &chains_.at(id) == &kept; });
  auto node = chains_.extract(*at);
  update.removed.push_back(node.key());
  node.key() = next_id_++;
  node.mapped().ghost_prev = again.prev;
  node.mapped().ghost_next = again.next;
  *at = node.key();
  update.added.emplace_back(node.key(), node.mapped());
  chains_.insert(chains_.end(), std::move(node));
}

// Stage "commit": each computed cell's new chains take the id of an equal old chain of the same
// box, or a fresh one (moved into the map, the index pointed at the map's node); old chains not
// taken, and those of gone cells whose box is gone, are removed.
void SurfaceState::commit(CellStore& store, std::span<const GoneCell> gone, ChainUpdate& update) {
  for (Computed& c : computed_) {
    std::vector<ChainId>& ids = store.at(c.box).chains;
    ids.clear();
    old_.clear();  // each old chain looked up once, not once per new chain
    for (ChainId id : c.old) old_.emplace_back(id, held(id));
    for (std::size_t k = c.first; k < c.first + c.count; ++k)
      ids.push_back(take(pending_[k], update));
    for (const auto& [id, at] : old_) remove(at, update);
  }
  for (const GoneCell& g : gone)
    if (!traced_now(store, g.box))
      for (ChainId id : g.chains) remove(held(id), update);
}

// The id of a new chain: an equal old one's (taken out of old_), or a fresh one. Ids only grow,
// so a fresh one goes at the map's end.
ChainId SurfaceState::take(SurfaceChain& chain, ChainUpdate& update) {
  const auto same = std::find_if(old_.begin(), old_.end(),
                                 [&](const OldChain& old) { return old.second->second == chain; });
  if (same != old_.end()) {
    const ChainId id = same->first;
    ends_.replace(&chain, same->second->second);
    old_.erase(same);
    return id;
  }
  const ChainId id = next_id_++;
  const auto it = chains_.emplace_hint(chains_.end(), id, std::move(chain));
  ends_.replace(&chain, it->second);
  update.added.emplace_back(id, it->second);
  return id;
}

std::map<ChainId, SurfaceChain>::iterator SurfaceState::held(ChainId id) {
  const auto at = chains_.find(id);
  if (at == chains_.end()) throw std::logic_error("game layer: a chain id without its chain");
  return at;
}

void SurfaceState::remove(std::map<ChainId, SurfaceChain>::iterator at, ChainUpdate& update) {
  update.removed.push_back(at->first);
  chains_.erase(at);
}

}  // namespace edgeland::game_detail
