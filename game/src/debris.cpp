#include "debris.hpp"

#include <algorithm>
#include <map>
#include <optional>

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

}  // namespace

std::vector<IslandRegion> island_regions(const Island& island, bool checked) {
  std::map<Material, PolygonSet> by_material;
  for (const IslandPiece& p : island.pieces) by_material[p.material].push_back(p.polygon);
  std::vector<IslandRegion> out;
  for (auto& [material, pieces] : by_material)
    out.push_back(merged_region(material, std::move(pieces), checked));
  return out;
}

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

DetachedAll detach_finished(Landscape& world, std::span<DebrisJob> jobs) {
  DetachedAll out;
  std::vector<PolygonRef> refs;
  for (DebrisJob& job : jobs) {
    if (!present(world, job.island(), refs)) {
      ++out.stale;
      continue;
    }
    out.debris.push_back(job.take());
  }
  // The polygons carved out by their ids: nothing to validate, nothing rounds.
  if (!refs.empty()) out.changes = world.remove(refs);
  return out;
}

}  // namespace edgeland::game_detail
