#include "game_state.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>
#include <string>

#include "debris.hpp"
#include "edgeland/clip/clip.hpp"
#include "island_walk.hpp"
#include "landscape_meshes.hpp"
#include "update_merge.hpp"

namespace edgeland::game_detail {
namespace {

// The island's key as IslandTree keeps it: the fingerprint of its polygons' ids.
IslandKey key_of(const Island& island) {
  IslandKey key = IslandKey::of(island.pieces.front().id);
  for (std::size_t i = 1; i < island.pieces.size(); ++i)
    key.add(IslandKey::of(island.pieces[i].id));
  return key;
}

// An edit that turns some non-solid material solid (a fill, in the game's terms).
bool fills(const Edit& e, const PhysicsMaterials& materials) {
  for (std::size_t m = 0; m < kMaterialCount; ++m) {
    const Material from = static_cast<std::uint8_t>(m);
    if (!materials.is_solid(from) && materials.is_solid(e.map[from])) return true;
  }
  return false;
}

// One polygon of a cell, for comparing the cells before and after a reset.
struct Held {
  PolygonId id;
  Material material;
  const Polygon* ring;
  Box64 cell;
  bool same(const Held& o) const {
    return id == o.id && material == o.material && *ring == *o.ring;
  }
};

void add_held(const CellContents& c, std::vector<Held>& out) {
  for (std::size_t i = 0; i < c.size(); ++i)
    out.push_back({c.ids()[i], c.material(i), &c.polygons()[i], c.box()});
}

// Whether `list` (ascending by id) holds the same polygon as `h`.
bool holds(const std::vector<Held>& list, const Held& h) {
  const auto [lo, hi] = std::equal_range(list.begin(), list.end(), h,
                                         [](const Held& l, const Held& r) { return l.id < r.id; });
  return std::any_of(lo, hi, [&](const Held& o) { return o.same(h); });
}

// The polygons of the cells a reset replaced, as a change set: those gone that the new cells do
// not hold (same id, ring and material) are removed, the new cells' others added.
ChangeSet changes_between(std::vector<Held> before, const CellStore& store,
                          std::span<const Box64> fresh) {
  std::vector<Held> after;
  for (const Box64& box : fresh) add_held(*store.at(box).scan.contents, after);
  const auto by_id = [](const Held& l, const Held& r) { return l.id < r.id; };
  std::sort(before.begin(), before.end(), by_id);
  std::sort(after.begin(), after.end(), by_id);
  ChangeSet out;
  out.cells.assign(fresh.begin(), fresh.end());
  for (const Held& b : before)
    if (!holds(after, b)) out.removed.push_back(b.id);
  for (const Held& a : after)
    if (!holds(before, a)) out.added.push_back({a.id, a.material, *a.ring, a.cell});
  return out;
}

std::vector<Held> held_in(std::span<const GoneCell> gone) {
  std::vector<Held> out;
  for (const GoneCell& g : gone) add_held(*g.contents, out);
  return out;
}

// Every polygon of `world` (whose cells must outlive the list).
std::vector<Held> held_in(const Landscape& world) {
  std::vector<Held> out;
  for (const Box64& box : all_cells(world)) add_held(*world.cell(box), out);
  return out;
}

// The options a later update would trip over, refused before anything is built: debris pieces
// of fewer than 3 vertices would throw from convex_pieces() in the middle of an update, after its
// edits were kept.
const GameOptions& checked(const GameOptions& options) {
  if (options.max_piece_vertices < 3) {
    throw InvalidArgument("max_piece_vertices", options.max_piece_vertices, 3);
  }
  return options;
}

}  // namespace

// A new driver's game holds the world's chains and meshes as it finds them (chains(),
// all_meshes()): that is what is delivered.
GameState::GameState(Landscape world, const GameOptions& options, ChainId first_chain_id)
    : options_(checked(options)),
      land_(std::move(world)),
      filled_(land_),
      surface_(options.surface, first_chain_id),
      delivered_(land_),
      delivered_before_(land_) {
  const std::vector<Box64> cells = all_cells(land_);
  store_.scan(land_, cells, options_.surface.materials);
  surface_.update(land_, store_, {}, cells);
  make_room_for(surface_.next_id());
  for (const auto& chain : surface_.chains()) hold_chain(chain.first, true);
  if (!options_.debris) return;
  islands_ = std::make_unique<IslandTree>(land_, store_, options_.surface.materials);
  queue_islands(islands_of(land_, store_, islands_->islands()));
}

std::unique_ptr<GameState> GameState::rebuilt(const GameState& failed, Landscape world,
                                              GameUpdate& out) {
  auto fresh =
      std::make_unique<GameState>(std::move(world), failed.options_, failed.surface_.next_id());
  const std::vector<Box64> cells = all_cells(fresh->land_);
  out = GameUpdate{};
  out.changes = changes_between(held_in(failed.delivered_), fresh->store_, cells);
  out.chains.removed = failed.held_chains();
  for (const auto& chain : fresh->surface_.chains()) out.chains.added.push_back(chain);
  finish_changes(out.changes, fresh->land_);
  finish_chains(out.chains);
  if (fresh->options_.meshes) out.meshes = landscape_mesh_update(out.changes);
  out.debris_waiting = fresh->queue_.size();
  return fresh;
}

// Stage "edit": the frame's edits as one batch (Landscape::apply_batch: one overlay per touched
// cell, rounded once; a batch of one is that edit), kept only when it succeeds.
ChangeSet GameState::edit(std::span<const Edit> edits) { return land_.apply_batch(edits); }

GameUpdate GameState::apply(std::span<const Edit> edits) {
  if (broken_)
    throw std::logic_error(std::string("GameDriver: an update stopped halfway (") +
                           broken_by_.data() + "); reset() it before applying");
  const Landscape before = land_;
  ChangeSet changes = edit(edits);  // the only step that may throw an input error
  return guarded([&] {
    GameUpdate out;
    start_work();
    note_fills(edits);
    filled_ = land_;  // before debris leaves it: a body in a fill that fell is buried too
    follow(before, changes, out);
    take_changes(out.changes, std::move(changes));
    drain_debris(out);
    trace_surface(out);
    finish(out);
    return out;
  });
}

GameUpdate GameState::reset(Landscape world) {
  return guarded([&] {
    land_ = std::move(world);
    fills_.clear();
    filled_ = land_;
    queue_.clear();
    GameUpdate out;
    start_work();
    differing_cells(land_, store_, replaced_, fresh_);
    replace_cells(replaced_, fresh_);
    out.changes = changes_between(held_in(gone_), store_, fresh_);
    if (islands_) {  // summaries made anew: every island of the world waits again
      islands_ = std::make_unique<IslandTree>(land_, store_, options_.surface.materials);
      queue_islands(islands_of(land_, store_, islands_->islands()));
    }
    drain_debris(out);
    trace_surface(out);
    finish(out);
    return out;
  });
}

// The stages of an update, then its delivery; anything thrown there (running out of memory, or
// an internal error a checked landscape found) leaves the state changed halfway: broken until
// rebuilt, the message kept to say why.
template <class Stages>
GameUpdate GameState::guarded(Stages&& stages) {
  try {
    GameUpdate out = stages();
    deliver(out);
    return out;
  } catch (const std::exception& e) {
    break_by(e.what());
    throw;
  } catch (...) {
    break_by("an exception of an unknown type");
    throw;
  }
}

void GameState::break_by(const char* why) noexcept {
  broken_ = true;
  const std::size_t n = std::min(std::strlen(why), broken_by_.size() - 1);
  std::copy_n(why, n, broken_by_.begin());
  broken_by_[n] = '\0';
}

// Everything that can run out of memory first (the bitmap's room, the lists of the delivery),
// then the bits and the landscapes, which cannot fail: the record is the old one or the new one.
void GameState::deliver(const GameUpdate& out) {
  last_delivery_ = false;
  make_room_for(surface_.next_id());
  last_added_.clear();
  for (const auto& chain : out.chains.added) last_added_.push_back(chain.first);
  last_removed_.assign(out.chains.removed.begin(), out.chains.removed.end());
  for (ChainId id : last_added_) hold_chain(id, true);
  for (ChainId id : last_removed_) hold_chain(id, false);
  delivered_before_ = delivered_;
  delivered_ = land_;
  last_delivery_ = true;
}

void GameState::update_lost() noexcept {
  if (last_delivery_) {
    for (ChainId id : last_added_) hold_chain(id, false);
    for (ChainId id : last_removed_) hold_chain(id, true);
    delivered_ = delivered_before_;
  }
  last_delivery_ = false;
  break_by("its last update did not reach the game: update_lost()");
}

void GameState::make_room_for(ChainId id) {
  if (delivered_chains_.size() <= id / 64) delivered_chains_.resize(id / 64 + 1, 0);
}

void GameState::hold_chain(ChainId id, bool held) noexcept {
  const std::uint64_t bit = std::uint64_t{1} << (id % 64);
  if (held)
    delivered_chains_[id / 64] |= bit;
  else
    delivered_chains_[id / 64] &= ~bit;
}

std::vector<ChainId> GameState::held_chains() const {
  std::vector<ChainId> out;
  for (std::size_t w = 0; w < delivered_chains_.size(); ++w)
    for (std::uint64_t bits = delivered_chains_[w]; bits != 0; bits &= bits - 1)
      out.push_back(w * 64 + static_cast<ChainId>(std::countr_zero(bits)));
  return out;
}

// Stage "follow": the change's cells replaced in the store (each new one scanned once), then
// the island summaries from the records (the chains wait for trace_surface).
void GameState::follow(const Landscape& before, const ChangeSet& changes, GameUpdate& out) {
  fresh_.clear();
  for (const Box64& box : changes.cells)
    if (land_.cell(box)) fresh_.push_back(box);  // a batch's step may re-cut a cell again
  std::sort(fresh_.begin(), fresh_.end(), box_less);
  fresh_.erase(std::unique(fresh_.begin(), fresh_.end()), fresh_.end());
  replaced_cells(before, fresh_, replaced_);
  replace_cells(replaced_, fresh_);
  if (!islands_) return;
  std::vector<Island> found = islands_of(land_, store_, islands_->update(land_, store_, fresh_));
  // A waiting island the change altered or tied to anchored ground is no island any more: its
  // job goes (what the change left of it, if still an island, is among those found, and keeps
  // its wait: a neighbour's detach re-cutting its cells must not restart the clock, or an island
  // could wait for ever).
  dropped_.clear();
  std::erase_if(queue_, [&](const Waiting& w) {
    if (islands_->holds(w.key)) return false;
    dropped_.push_back({w.job.bounds(), w.age});
    return true;
  });
  out.work.islands_found += found.size();
  queue_islands(std::move(found));
}

// How long an island found now has waited: the longest wait of a dropped job whose box meets
// its own (what an altered island left is within the old one's box), else 0.
std::size_t GameState::waited(const Box64& bounds) const {
  std::size_t age = 0;
  for (const auto& [box, dropped_age] : dropped_)
    if (box.overlaps(bounds)) age = std::max(age, dropped_age);
  return age;
}

// Each before the first job that has waited less: an island found again keeps its wait, which
// may be longer than that of jobs queued after its first finding, and advance_jobs() stops at the
// first job that stops (a longer wait behind a shorter one could pass max_debris_wait).
void GameState::queue_islands(std::vector<Island> islands) {
  for (Island& island : islands) {
    const IslandKey key = key_of(island);
    const std::size_t age = waited(island.bounds);
    const auto at =
        std::find_if(queue_.begin(), queue_.end(), [&](const Waiting& w) { return w.age < age; });
    queue_.insert(at, {DebrisJob(std::move(island), store_, land_.checked()), key, age});
  }
}

// The records of `replaced` leave the store and those of `fresh` are scanned into it. A replaced
// cell scanned earlier in this update (debris carved where the edits just were) was never
// traced: it leaves no trace behind, and the gone cells keep what the chains were made from.
void GameState::replace_cells(std::span<const Box64> replaced, std::span<const Box64> fresh) {
  traced_before_.clear();
  scanned_now_.clear();
  for (const Box64& box : replaced) {
    const auto at = std::lower_bound(untraced_.begin(), untraced_.end(), box, box_less);
    if (at != untraced_.end() && *at == box) {
      untraced_.erase(at);
      scanned_now_.push_back(box);
    } else {
      traced_before_.push_back(box);
    }
  }
  store_.remove(traced_before_, gone_);
  store_.drop(scanned_now_);
  store_.scan(land_, fresh, options_.surface.materials);
  for (const Box64& box : fresh) {
    const auto at = std::lower_bound(untraced_.begin(), untraced_.end(), box, box_less);
    if (at == untraced_.end() || *at != box) untraced_.insert(at, box);
  }
}

// Stage "surface": the chains of the cells the update's edits and debris left, traced once from
// what they were at the last update (the gone cells) to what they are now.
void GameState::trace_surface(GameUpdate& out) {
  if (untraced_.empty() && gone_.empty()) return;
  if (land_.checked()) check_before_surface();
  take_chains(out.chains, surface_.update(land_, store_, gone_, untraced_));
  out.work.cells_traced += surface_.last_traced();
  gone_.clear();
  untraced_.clear();
}

// Stage "debris": the queued islands' jobs advanced, those finished carved out in one edit,
// then followed.
void GameState::drain_debris(GameUpdate& out) {
  if (queue_.empty()) return;
  if (land_.checked()) check_queue_order();
  std::vector<DebrisJob> finished = advance_jobs();
  if (land_.checked()) check_waits_bounded();
  for (Waiting& w : queue_) ++w.age;
  if (finished.empty()) return;
  const Landscape before = land_;
  DetachedAll detached = detach_finished(land_, finished);
  if (!detached.changes.cells.empty()) follow(before, detached.changes, out);
  take_changes(out.changes, std::move(detached.changes));
  out.work.islands_detached += detached.debris.size();
  for (Debris& d : detached.debris) out.debris.push_back(std::move(d));
}

// Oldest first, while the budget lasts; the first gets a step whatever it costs unless it was
// found in this update (which already paid for the edit and for finding it: a big island's first
// step, its merge, waits for the next), and a job that has waited options_.max_debris_wait
// updates is finished whatever the budget. Queued later, a job has waited no longer than those
// before it, so the first that stops ends the pass.
DebrisJob::Pace GameState::pace_of(const Waiting& w) const {
  if (w.age >= options_.max_debris_wait) return DebrisJob::Pace::kFinish;
  return w.age == 0 ? DebrisJob::Pace::kWithinBudget : DebrisJob::Pace::kFirstStep;
}

std::vector<DebrisJob> GameState::advance_jobs() {
  std::vector<DebrisJob> finished;
  std::size_t spent = 0;
  while (!queue_.empty()) {
    Waiting& w = queue_.front();
    if (!w.job.advance(options_, spent, pace_of(w))) break;
    finished.push_back(std::move(w.job));
    queue_.pop_front();
  }
  return finished;
}

// Stage "finish": the merged lists in order, the meshes of what the update added.
void GameState::finish(GameUpdate& out) const {
  finish_changes(out.changes, land_);
  finish_chains(out.chains);
  if (options_.meshes) out.meshes = landscape_mesh_update(out.changes);
  out.debris_waiting = queue_.size();
  out.work.cells_scanned = static_cast<std::size_t>(store_.scans() - scans_before_);
  out.work.boundary_passes = static_cast<std::size_t>(solid_boundary_runs() - passes_before_);
}

// Checked mode: what the surface stage is handed (game/README.md, the invariant before it). Every
// untraced box is a cell of the landscape with its record; a gone cell whose box the landscape
// has again was scanned again (else its chains would be dropped for a cell that still holds them).
void GameState::check_before_surface() const {
  const auto untraced = [&](const Box64& box) {
    return std::binary_search(untraced_.begin(), untraced_.end(), box, box_less);
  };
  for (const Box64& box : untraced_)
    if (!land_.cell(box) || !store_.find(box))
      throw std::logic_error("game layer: an untraced cell the landscape or the store lacks");
  for (const GoneCell& g : gone_)
    if (land_.cell(g.box) && !untraced(g.box))
      throw std::logic_error("game layer: a gone cell the landscape has, not scanned again");
}

// Checked mode: the bound game/README.md promises (no island waits more than max_debris_wait + 1
// updates): after the jobs advanced, none that has waited its limit is still queued.
void GameState::check_waits_bounded() const {
  for (const Waiting& w : queue_)
    if (w.age >= options_.max_debris_wait)
      throw std::logic_error("game layer: a queued island has waited its limit and is not done");
}

// Checked mode: what the debris stage is handed. advance_jobs() stops at the first job that
// stops, which bounds every wait only if no job waited longer than one queued before it.
void GameState::check_queue_order() const {
  for (std::size_t i = 1; i < queue_.size(); ++i)
    if (queue_[i].age > queue_[i - 1].age)
      throw std::logic_error("game layer: a queued island has waited longer than one before it");
}

void GameState::start_work() {
  gone_.clear();
  untraced_.clear();
  scans_before_ = store_.scans();
  passes_before_ = solid_boundary_runs();
}

void GameState::note_fills(std::span<const Edit> edits) {
  fills_.clear();
  for (const Edit& e : edits)
    if (fills(e, options_.surface.materials))
      if (const std::optional<Box64> box = bounding_box(e.shape.polygons()))
        fills_.push_back({e.shape, *box});
}

// The box meets a filling shape's interior where the edits left solid (before any of it fell as
// debris): the shape cut to the box (the clipper's one rounding), then overlaps().
bool GameState::buried(const Box64& box) const {
  if (box.min.x >= box.max.x || box.min.y >= box.max.y) return false;
  for (const Fill& fill : fills_) {
    if (!fill.box.overlaps_open(box)) continue;
    const ValidClipResult inside = clip_to_box(fill.shape, box);
    if (inside.set.polygons().empty()) continue;
    for (Material m : filled_.overlaps(inside.set))
      if (options_.surface.materials.is_solid(m)) return true;
  }
  return false;
}

}  // namespace edgeland::game_detail
