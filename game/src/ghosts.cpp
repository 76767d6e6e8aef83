#include "ghosts.hpp"

#include "chain_tracing.hpp"
#include "edgeland/kernel/around_vertex.hpp"
#include "edgeland/kernel/scratch.hpp"

namespace edgeland::game_detail {
namespace {

Point64 minus(Point64 a, Point64 b) { return {a.x - b.x, a.y - b.y}; }

// The chains around p whose first (starting) or last (ending) point is p, and for each the
// direction of its segment at p.
// Scratch storage (scratch.hpp): asked twice for every chain an update traces, these allocated
// three arrays each time.
struct Candidates {
  detail::ScratchVector<const SurfaceChain*> chains;
  detail::ScratchVector<Point64> directions;
};

Candidates candidates_at(const ChainsAround& around, Point64 p, bool starting) {
  detail::ScratchVector<const SurfaceChain*> all;
  around(p, all);
  Candidates out;
  for (const SurfaceChain* c : all) {
    if (c->closed) continue;
    const std::size_t n = c->points.size();
    if (starting && c->points.front() == p) {
      out.chains.push_back(c);
      out.directions.push_back(minus(c->points[1], p));
    } else if (!starting && c->points.back() == p) {
      out.chains.push_back(c);
      out.directions.push_back(minus(c->points[n - 2], p));
    }
  }
  return out;
}

}  // namespace

Point64 straight_on(Point64 end, Point64 before) {
  return {2 * end.x - before.x, 2 * end.y - before.y};
}

const SurfaceChain* following(const SurfaceChain& chain, const ChainsAround& around,
                              const Box64& world, bool border_wall) {
  const Point64 t = chain.points.back();
  const Candidates c = candidates_at(around, t, true);
  const auto pick = first_clockwise(minus(chain.points[chain.points.size() - 2], t), c.directions,
                                    quadrants_outside_world(world, border_wall, t));
  return pick ? c.chains[*pick] : nullptr;
}

const SurfaceChain* preceding(const SurfaceChain& chain, const ChainsAround& around,
                              const Box64& world, bool border_wall) {
  const Point64 s = chain.points.front();
  const Candidates c = candidates_at(around, s, false);
  const auto pick = first_counterclockwise(minus(chain.points[1], s), c.directions,
                                           quadrants_outside_world(world, border_wall, s));
  return pick ? c.chains[*pick] : nullptr;
}

Ghosts ghosts_of(const SurfaceChain& chain, const ChainsAround& around, const Box64& world,
                 bool border_wall) {
  const std::size_t n = chain.points.size();
  const SurfaceChain* next = following(chain, around, world, border_wall);
  const SurfaceChain* prev = preceding(chain, around, world, border_wall);
  return {
      prev ? prev->points[prev->points.size() - 2] : straight_on(chain.points[0], chain.points[1]),
      next ? next->points[1] : straight_on(chain.points[n - 1], chain.points[n - 2])};
}

void set_ghosts(SurfaceChain& chain, const ChainsAround& around, const Box64& world,
                bool border_wall) {
  if (chain.closed) return;
  const Ghosts g = ghosts_of(chain, around, world, border_wall);
  chain.ghost_prev = g.prev;
  chain.ghost_next = g.next;
}

void ChainEndIndex::add(const SurfaceChain& chain) {
  if (chain.closed) return;
  table_.insert(chain.points.front(), &chain);
  if (chain.points.back() != chain.points.front()) table_.insert(chain.points.back(), &chain);
}

void ChainEndIndex::remove(const SurfaceChain& chain) {
  if (chain.closed) return;
  table_.erase(chain.points.front(), &chain);
  if (chain.points.back() != chain.points.front()) table_.erase(chain.points.back(), &chain);
}

void ChainEndIndex::replace(const SurfaceChain* from, const SurfaceChain& to) {
  if (to.closed) return;
  table_.replace(to.points.front(), from, &to);
  if (to.points.back() != to.points.front()) table_.replace(to.points.back(), from, &to);
}

void ChainEndIndex::chains_at(Point64 p, std::vector<const SurfaceChain*>& out) const {
  table_.append(p, out);
}

ChainsAround ChainEndIndex::lookup() const {
  return [this](Point64 p, std::vector<const SurfaceChain*>& out) { chains_at(p, out); };
}

}  // namespace edgeland::game_detail
