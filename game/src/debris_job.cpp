#include "debris_job.hpp"

#include <map>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/assert.hpp"
#include "edgeland/kernel/centroid.hpp"
#include "edgeland/kernel/convex_pieces.hpp"
#include "edgeland/kernel/triangulation.hpp"

namespace edgeland::game_detail {
namespace {

std::size_t vertices_of(const PolygonSet& set) {
  std::size_t n = 0;
  for (const Polygon& p : set) n += p.size();
  return n;
}

}  // namespace

// One piece is its own merge: a landscape polygon is in canonical form, as merge_tiles writes
// it (most islands a game cuts loose are one polygon; checked mode compares the two).
IslandRegion merged_region(Material material, PolygonSet pieces, bool checked) {
  if (pieces.size() == 1 && !checked) return {material, std::move(pieces)};
  PolygonSet merged = merge_tiles(ValidSet(pieces), {.checked = checked}).set.polygons();
  if (checked && pieces.size() == 1 && merged != pieces)
    detail::fail_stage("debris", "a one-polygon island's merge is not the polygon itself");
  return {material, std::move(merged)};
}

// The area, centroid and bounds are the island's (exact, O(n)); the rest waits for the steps.
DebrisJob::DebrisJob(Island island, bool checked) : island_(std::move(island)), checked_(checked) {
  std::map<Material, PolygonSet> by_material;
  PolygonSet all;
  for (const IslandPiece& p : island_.pieces) {
    by_material[p.material].push_back(p.polygon);
    all.push_back(p.polygon);
  }
  materials_.assign(by_material.begin(), by_material.end());
  vertices_ = vertices_of(all);
  debris_.twice_area = island_.twice_area;
  debris_.centroid = centroid(all);
  debris_.bounds = island_.bounds;
}

bool DebrisJob::done() const noexcept {
  return merged_ == materials_.size() && region_ == debris_.regions.size();
}

std::size_t DebrisJob::next_cost() const {
  if (merged_ < materials_.size()) return vertices_of(materials_[merged_].second);
  return debris_.regions[region_].polygons[polygon_].size();
}

// One material merged, or one merged polygon cut into convex pieces (and meshed).
void DebrisJob::step(const GameOptions& options) {
  if (merged_ < materials_.size()) {
    auto& [material, pieces] = materials_[merged_++];
    IslandRegion merged = merged_region(material, std::move(pieces), checked_);
    if (!merged.polygons.empty()) debris_.regions.push_back(std::move(merged));
    return;
  }
  const IslandRegion& r = debris_.regions[region_];
  const Polygon& p = r.polygons[polygon_];
  // The mesh's triangles are the pieces' first stage: made once. The polygon is merge_tiles'
  // output (or a landscape polygon): valid, so not validated again.
  TrianglesAndPieces both =
      detail::triangles_and_convex_pieces_valid(p, options.max_piece_vertices);
  add_pieces(r.material, std::move(both.pieces));
  if (options.meshes) debris_.meshes.push_back({0, r.material, p, std::move(both.triangles)});
  if (++polygon_ == r.polygons.size()) ++region_, polygon_ = 0;
}

void DebrisJob::add_pieces(Material material, std::vector<Polygon> pieces) {
  for (Polygon& piece : pieces) debris_.pieces.push_back({material, std::move(piece)});
}

bool DebrisJob::advance(const GameOptions& options, std::size_t& spent, Pace pace) {
  while (!done()) {
    const std::size_t cost = next_cost();
    const bool forced = pace == Pace::kFinish || (pace == Pace::kFirstStep && spent == 0);
    if (!forced && spent + cost > options.debris_budget) break;
    step(options);
    spent += cost;
  }
  return done();
}

}  // namespace edgeland::game_detail
