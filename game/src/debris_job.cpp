#include "debris_job.hpp"

#include <algorithm>
#include <map>
#include <tuple>

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

ValidSet joined_pieces(std::span<const CellPieces> pieces) {
  std::vector<ValidSet> parts;
  parts.reserve(pieces.size());
  for (const CellPieces& c : pieces) parts.push_back(subset(c.cell.set(), c.members));
  std::vector<BoxedSet> boxed;
  for (std::size_t i = 0; i < pieces.size(); ++i)
    boxed.push_back({&parts[i], pieces[i].cell.box()});
  return join(boxed);
}

// The area, centroid and bounds are the island's (exact, O(n)); the rest waits for the steps.
DebrisJob::DebrisJob(Island island, const CellStore& store, bool checked)
    : island_(std::move(island)), checked_(checked) {
  // Each piece found among its cell's polygons, grouped by material and then by cell.
  std::map<Material,
           std::map<std::tuple<std::int64_t, std::int64_t, std::int64_t, std::int64_t>, CellPieces>>
      by_material;
  PolygonSet all;
  for (const IslandPiece& p : island_.pieces) {
    const CellContents& cell = *store.at(p.cell).scan.contents;
    const auto ids = cell.ids();
    const auto at = static_cast<std::size_t>(std::find(ids.begin(), ids.end(), p.id) - ids.begin());
    if (at == ids.size()) detail::fail_stage("debris", "an island's piece is not in its cell");
    auto& pieces = by_material[p.material];
    auto [it, added] = pieces.try_emplace({p.cell.min.x, p.cell.min.y, p.cell.max.x, p.cell.max.y},
                                          CellPieces{cell, {}});
    it->second.members.push_back(at);
    all.push_back(p.polygon);
  }
  for (auto& [material, cells] : by_material) {
    std::vector<CellPieces> list;
    for (auto& [box, c] : cells) {
      std::sort(c.members.begin(), c.members.end());
      list.push_back(std::move(c));
    }
    materials_.emplace_back(material, std::move(list));
  }
  vertices_ = vertices_of(all);
  debris_.twice_area = island_.twice_area;
  debris_.centroid = centroid(all);
  debris_.bounds = island_.bounds;
}

bool DebrisJob::done() const noexcept {
  return merged_ == materials_.size() && region_ == debris_.regions.size();
}

std::size_t DebrisJob::next_cost() const {
  if (merging_) return merging_->ring_vertices();
  if (merged_ < materials_.size()) {
    std::size_t n = 0;
    for (const CellPieces& c : materials_[merged_].second)
      for (std::size_t i : c.members) n += c.cell.polygons()[i].size();
    return n;
  }
  return debris_.regions[region_].polygons[polygon_].size();
}

// Half of one material's merge (its boundary traced, or its holes split), or one merged polygon
// cut into convex pieces (and meshed).
void DebrisJob::step(const GameOptions& options) {
  if (merged_ < materials_.size()) return merge_step();
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

// One piece is its own merge: a landscape polygon is in canonical form, as merge_tiles writes it
// (most islands a game cuts loose are one polygon; checked mode compares the two). More are
// merged in two steps (TileMerge), so a big island's merge is two updates' work, not one.
void DebrisJob::merge_step() {
  const Material material = materials_[merged_].first;
  if (!merging_) {
    ValidSet joined = joined_pieces(materials_[merged_].second);
    if (joined.polygons().size() == 1 && !checked_) {
      debris_.regions.push_back({material, joined.polygons()});
      ++merged_;
      return;
    }
    merging_.emplace(joined, ClipOptions{.checked = checked_});
    if (joined.polygons().size() == 1) single_ = joined.polygons().front();
    return;
  }
  PolygonSet merged = std::move(*merging_).finish().set.polygons();
  merging_.reset();
  if (single_ && merged != PolygonSet{*single_})
    detail::fail_stage("debris", "a one-polygon island's merge is not the polygon itself");
  single_.reset();
  if (!merged.empty()) debris_.regions.push_back({material, std::move(merged)});
  ++merged_;
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
