#include "debris.hpp"

#include <algorithm>
#include <map>
#include <optional>

#include "edgeland/clip/clip.hpp"
#include "edgeland/game/render_meshes.hpp"
#include "edgeland/kernel/centroid.hpp"
#include "edgeland/kernel/convex_pieces.hpp"

namespace edgeland::game_detail {
namespace {

// Where the landscape holds the piece now: the cell whose box holds the polygon's and whose
// polygons include its id (an unchanged polygon keeps its id, also in a cell split or merged
// since the island was found; ids are never reused).
std::optional<PolygonRef> current(const Landscape& world, const IslandPiece& piece) {
  const Box64 bounds = *bounding_box(piece.polygon);
  std::optional<PolygonRef> out;
  world.cells_in({bounds.min, bounds.min}, [&](const CellView& c) {
    if (!c.box.contains(bounds)) return true;
    const std::span<const PolygonId> ids = world.cell(c.box)->ids();
    if (std::find(ids.begin(), ids.end(), piece.id) != ids.end()) out = PolygonRef{piece.id, c.box};
    return !out;
  });
  return out;
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

bool present(const Landscape& world, const Island& island, std::vector<PolygonRef>& refs) {
  const std::size_t first = refs.size();
  for (const IslandPiece& p : island.pieces) {
    const std::optional<PolygonRef> ref = current(world, p);
    if (!ref) {
      refs.resize(first);
      return false;
    }
    refs.push_back(*ref);
  }
  return true;
}

Debris debris_of(const Island& island, const GameOptions& options) {
  Debris d;
  d.regions = regions_of(island);
  d.pieces = pieces_of(d.regions, options.max_piece_vertices);
  if (options.meshes)
    for (const Debris::Region& r : d.regions)
      for (const Polygon& p : r.polygons) d.meshes.push_back(polygon_mesh(0, r.material, p));
  d.twice_area = island.twice_area;
  PolygonSet all;
  for (const IslandPiece& p : island.pieces) all.push_back(p.polygon);
  d.centroid = centroid(all);
  d.bounds = island.bounds;
  return d;
}

DetachedAll detach_islands(Landscape& world, std::span<const Island> islands,
                           const GameOptions& options) {
  DetachedAll out;
  std::vector<PolygonRef> refs;
  for (const Island& island : islands) {
    if (!present(world, island, refs)) {
      ++out.stale;
      continue;
    }
    out.debris.push_back(debris_of(island, options));
  }
  // The polygons carved out by their ids: nothing to validate, nothing rounds.
  if (!refs.empty()) out.changes = world.remove(refs);
  return out;
}

}  // namespace edgeland::game_detail
