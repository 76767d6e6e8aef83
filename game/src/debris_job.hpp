#pragma once
// One island's debris made in steps (GameOptions::debris_budget), so that a big island spreads
// its work over a few updates instead of stalling one: first each material's merge into maximal
// polygons (clip's TileMerge, in two steps: the boundary traced, then the holes split; one piece
// is its own merge), then the convex pieces (and mesh) of one merged polygon at a time. A
// step's cost is the vertices it reads. The island stays in the landscape until the job
// is done and the driver carves it out (debris.hpp, detach_prepared); if an edit changed it
// meanwhile, the carve finds it stale and drops the job (the island tracker has queued what the
// edit left).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cell_store.hpp"
#include "edgeland/clip/clip.hpp"
#include "edgeland/game/game_types.hpp"
#include "edgeland/game/islands.hpp"

namespace edgeland::game_detail {

// One material's pieces of an island merged into maximal polygons (polygons that touch along
// cell lines and bridges, never crossing: nothing rounds).
IslandRegion merged_region(Material material, PolygonSet pieces, bool checked);

// Some of one cell's polygons, as the landscape holds them: a valid set of the cell's, so an
// island's pieces, cell by cell, make a valid set without validating again (clip's join()).
struct CellPieces {
  CellContents cell;
  std::vector<std::size_t> members;  // ascending
};
// The pieces as one valid set, cell by cell (clip's join(): nothing validated again).
ValidSet joined_pieces(std::span<const CellPieces> pieces);

class DebrisJob {
 public:
  // `store` holds the cells the island was found in (its pieces' cells).
  DebrisJob(Island island, const CellStore& store, bool checked);

  // How far advance() goes past the budget.
  enum class Pace : std::uint8_t {
    kWithinBudget,  // only steps that fit
    kFirstStep,     // and one step whatever its cost when nothing is spent yet
    kFinish,        // every step left
  };
  // Steps while their costs fit in options.debris_budget - `spent` (adding them to `spent`),
  // as far as `pace` allows. Returns done().
  bool advance(const GameOptions& options, std::size_t& spent, Pace pace);
  bool done() const noexcept;
  // The island's bounding box.
  const Box64& bounds() const noexcept { return debris_.bounds; }
  const Island& island() const noexcept { return island_; }
  std::size_t vertices() const noexcept { return vertices_; }
  Debris take() { return std::move(debris_); }

 private:
  std::size_t next_cost() const;
  void step(const GameOptions& options);
  void add_pieces(Material material, std::vector<Polygon> pieces);

  Island island_;
  bool checked_;
  std::size_t vertices_ = 0;
  // Pieces to merge, ascending material, each material's by cell.
  std::vector<std::pair<Material, std::vector<CellPieces>>> materials_;
  void merge_step();

  std::size_t merged_ = 0;                // materials merged so far
  std::optional<TileMerge> merging_;      // the current material's merge, its boundary traced
  std::optional<Polygon> single_;         // checked mode: the one piece merging_ holds
  std::size_t region_ = 0, polygon_ = 0;  // next merged polygon to cut
  Debris debris_;
};

}  // namespace edgeland::game_detail
