// The public surface exports (surface_chains.hpp): every cell's chains, then their ghosts; or
// the chains joined into whole loops.
#include "edgeland/game/surface_chains.hpp"

#include <unordered_set>

#include "cell_store.hpp"
#include "chain_tracing.hpp"
#include "ghosts.hpp"
#include "surface_state.hpp"

namespace edgeland {
namespace {

using game_detail::ChainEndIndex;
using game_detail::ChainsAround;

// The chains of every cell with their ghosts, cell by cell in tree order (the ids of a surface
// state made at once follow that order).
std::vector<SurfaceChain> all_chains(const Landscape& world, const SurfaceOptions& options) {
  const std::vector<Box64> cells = game_detail::all_cells(world);
  game_detail::CellStore store;
  store.scan(world, cells, options.materials);
  game_detail::SurfaceState surface(options);
  surface.update(world, store, {}, cells);
  std::vector<SurfaceChain> out;
  out.reserve(surface.chains().size());
  for (const auto& [id, chain] : surface.chains()) out.push_back(chain);
  return out;
}

ChainEndIndex ends_of(const std::vector<SurfaceChain>& chains) {
  ChainEndIndex ends;
  for (const SurfaceChain& c : chains) ends.add(c);
  return ends;
}

// Appends `more` (which starts where `into` ends) to `into`.
void append(game_detail::TracedChain& into, const SurfaceChain& more) {
  into.points.insert(into.points.end(), more.points.begin() + 1, more.points.end());
  into.materials.insert(into.materials.end(), more.materials.begin(), more.materials.end());
}

// The loop through `first` along `following` links, marking the chains it takes.
using Taken = std::unordered_set<const SurfaceChain*>;

SurfaceChain join_from(const SurfaceChain* first, const ChainsAround& around, const Box64& world,
                       bool border_wall, Taken& taken) {
  game_detail::TracedChain loop;
  loop.points.push_back(first->points.front());
  const SurfaceChain* c = first;
  while (c && taken.insert(c).second) {
    append(loop, *c);
    c = c->closed ? nullptr : game_detail::following(*c, around, world, border_wall);
  }
  // A chain closed in its cell repeats no point; a cycle of open chains ends where it began.
  loop.closed = first->closed || c == first;
  if (!first->closed && loop.closed) loop.points.pop_back();
  game_detail::make_canonical(loop);
  SurfaceChain out;
  out.points = std::move(loop.points);
  out.materials = std::move(loop.materials);
  out.closed = loop.closed;
  out.cell = world;
  const std::size_t n = out.points.size();
  out.ghost_prev =
      out.closed ? out.points.back() : game_detail::straight_on(out.points[0], out.points[1]);
  out.ghost_next = out.closed ? out.points.front()
                              : game_detail::straight_on(out.points[n - 1], out.points[n - 2]);
  return out;
}

}  // namespace

std::vector<SurfaceChain> surface_chains(const Landscape& world, const SurfaceOptions& options) {
  return all_chains(world, options);
}

std::vector<SurfaceChain> surface_loops(const Landscape& world, const SurfaceOptions& options) {
  const std::vector<SurfaceChain> chains = all_chains(world, options);
  const ChainEndIndex ends = ends_of(chains);
  const ChainsAround around = ends.lookup();
  const Box64& box = world.world();
  std::vector<SurfaceChain> out;
  Taken taken;
  // Closed in one cell, open at the world border, then the cycles through several cells.
  for (const SurfaceChain& c : chains)
    if (c.closed) out.push_back(join_from(&c, around, box, options.border_wall, taken));
  for (const SurfaceChain& c : chains)
    if (!c.closed && !game_detail::preceding(c, around, box, options.border_wall))
      out.push_back(join_from(&c, around, box, options.border_wall, taken));
  for (const SurfaceChain& c : chains)
    if (!taken.count(&c)) out.push_back(join_from(&c, around, box, options.border_wall, taken));
  return out;
}

}  // namespace edgeland
