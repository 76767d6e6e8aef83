// detach (islands.hpp): an island carved out with its own polygons as the shape, whose edges are
// the landscape's edges, so the overlay meets no crossing and rounds nothing.

#include "debris.hpp"
#include "edgeland/clip/clip.hpp"
#include "edgeland/game/islands.hpp"
#include "edgeland/kernel/centroid.hpp"

namespace edgeland {
namespace {

// Whether the landscape still holds the piece: the same id with the same ring and material.
bool present(const Landscape& world, const IslandPiece& piece) {
  bool found = false;
  world.polygons_in(*bounding_box(piece.polygon), [&](const PolygonView& v) {
    found = v.id == piece.id && v.material == piece.material && *v.polygon == piece.polygon;
    return !found;
  });
  return found;
}

}  // namespace

StaleIsland::StaleIsland(PolygonId p)
    : Error("island polygon " + std::to_string(p) + " is no longer in the landscape"), polygon(p) {}

DetachedIsland detach(Landscape& world, const Island& island) {
  PolygonSet pieces;
  for (const IslandPiece& p : island.pieces) {
    if (!present(world, p)) throw StaleIsland(p.id);
    pieces.push_back(p.polygon);
  }
  DetachedIsland out;
  out.regions = game_detail::island_regions(island, world.checked());
  out.twice_area = island.twice_area;
  out.centroid = centroid(pieces);
  // Last: the only step that changes the landscape (the strong guarantee of carve).
  out.changes = world.carve(ValidSet(std::move(pieces)));
  return out;
}

}  // namespace edgeland
