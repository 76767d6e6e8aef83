#include "ghosts.hpp"

#include "chain_tracing.hpp"
#include "edgeland/kernel/around_vertex.hpp"

namespace edgeland::game_detail {
namespace {

Point64 minus(Point64 a, Point64 b) { return {a.x - b.x, a.y - b.y}; }
Point64 beyond(Point64 end, Point64 before) { return {2 * end.x - before.x, 2 * end.y - before.y}; }

const std::vector<const SurfaceChain*>* chains_at(
    const std::unordered_map<Point64, std::vector<const SurfaceChain*>, Point64Hash>& map,
    Point64 p) {
  const auto it = map.find(p);
  return it == map.end() ? nullptr : &it->second;
}

}  // namespace

void ChainEnds::add(const SurfaceChain& chain) {
  if (chain.closed) return;
  starting_[chain.points.front()].push_back(&chain);
  ending_[chain.points.back()].push_back(&chain);
}

const SurfaceChain* ChainEnds::following(const SurfaceChain& chain, const Box64& world,
                                         bool border_wall) const {
  const Point64 t = chain.points.back();
  const auto* candidates = chains_at(starting_, t);
  if (!candidates) return nullptr;
  std::vector<Point64> dirs;
  for (const SurfaceChain* c : *candidates) dirs.push_back(minus(c->points[1], t));
  const auto pick = first_clockwise(minus(chain.points[chain.points.size() - 2], t), dirs,
                                    quadrants_outside_world(world, border_wall, t));
  return pick ? (*candidates)[*pick] : nullptr;
}

const SurfaceChain* ChainEnds::preceding(const SurfaceChain& chain, const Box64& world,
                                         bool border_wall) const {
  const Point64 s = chain.points.front();
  const auto* candidates = chains_at(ending_, s);
  if (!candidates) return nullptr;
  std::vector<Point64> dirs;
  for (const SurfaceChain* c : *candidates) dirs.push_back(minus(c->points[c->points.size() - 2], s));
  const auto pick = first_counterclockwise(minus(chain.points[1], s), dirs,
                                           quadrants_outside_world(world, border_wall, s));
  return pick ? (*candidates)[*pick] : nullptr;
}

void set_ghosts(SurfaceChain& chain, const ChainEnds& ends, const Box64& world, bool border_wall) {
  if (chain.closed) return;
  const std::size_t n = chain.points.size();
  const SurfaceChain* next = ends.following(chain, world, border_wall);
  chain.ghost_next = next ? next->points[1] : beyond(chain.points[n - 1], chain.points[n - 2]);
  const SurfaceChain* prev = ends.preceding(chain, world, border_wall);
  chain.ghost_prev = prev ? prev->points[prev->points.size() - 2] : beyond(chain.points[0], chain.points[1]);
}

}  // namespace edgeland::game_detail
