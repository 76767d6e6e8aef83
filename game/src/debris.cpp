#include "debris.hpp"

#include <map>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/centroid.hpp"
#include "edgeland/kernel/convex_pieces.hpp"

namespace edgeland::game_detail {
namespace {

bool holds(const Landscape& world, const IslandPiece& piece) {
  bool found = false;
  world.polygons_in(*bounding_box(piece.polygon), [&](const PolygonView& v) {
    found = v.id == piece.id && v.material == piece.material && *v.polygon == piece.polygon;
    return !found;
  });
  return found;
}

// The island's region per material as maximal polygons: its pieces merged (one union of
// polygons that touch along cell lines and bridges, no crossing: nothing rounds).
std::vector<Debris::Region> regions_of(const Island& island) {
  std::map<Material, PolygonSet> by_material;
  for (const IslandPiece& p : island.pieces) by_material[p.material].push_back(p.polygon);
  std::vector<Debris::Region> out;
  for (auto& [material, pieces] : by_material)
    out.push_back({material, merge(ValidSet(std::move(pieces))).set.polygons()});
  return out;
}

std::vector<DebrisPiece> pieces_of(const std::vector<Debris::Region>& regions,
                                   std::size_t max_vertices) {
  std::vector<DebrisPiece> out;
  for (const Debris::Region& r : regions)
    for (const Polygon& polygon : r.polygons)
      for (Polygon& piece : convex_pieces(polygon, max_vertices))
        out.push_back({r.material, std::move(piece)});
  return out;
}

}  // namespace

bool present(const Landscape& world, const Island& island) {
  for (const IslandPiece& p : island.pieces)
    if (!holds(world, p)) return false;
  return true;
}

Debris debris_of(const Island& island, std::size_t max_piece_vertices) {
  Debris d;
  d.regions = regions_of(island);
  d.pieces = pieces_of(d.regions, max_piece_vertices);
  d.twice_area = island.twice_area;
  PolygonSet all;
  for (const IslandPiece& p : island.pieces) all.push_back(p.polygon);
  d.centroid = centroid(all);
  d.bounds = island.bounds;
  return d;
}

DetachedAll detach_islands(Landscape& world, std::span<const Island> islands,
                           std::size_t max_piece_vertices) {
  DetachedAll out;
  PolygonSet carved;
  for (const Island& island : islands) {
    if (!present(world, island)) {
      ++out.stale;
      continue;
    }
    out.debris.push_back(debris_of(island, max_piece_vertices));
    for (const IslandPiece& p : island.pieces) carved.push_back(p.polygon);
  }
  // Islands touch one another at points at most: their polygons together are a valid set.
  if (!carved.empty()) out.changes = world.carve(ValidSet(std::move(carved)));
  return out;
}

}  // namespace edgeland::game_detail
