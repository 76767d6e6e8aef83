#pragma once
// The landscape's value types (landscape.hpp is the front end, errors.hpp its errors): what a
// landscape is configured with, what its queries and edits hand out. Plain data, no behaviour.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "edgeland/clip/valid_set.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/fraction.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/spatial/material.hpp"

namespace edgeland {

using PolygonId = std::uint64_t;

enum class TreeKind : std::uint8_t {
  kQuadtree,  // four children, cut at both midpoint lines
  kKdTree,    // two children, cut at the midpoint of the longer side (x on ties)
};

struct LandscapeConfig {
  TreeKind tree = TreeKind::kQuadtree;
  // A cell whose polygons have more edges than this splits (unless both its sides are at most
  // min_cell_size); siblings whose cells together have at most merge_below edges merge back.
  // merge_below < edge_cap is the hysteresis that keeps a digger going back and forth over a
  // cell line from splitting and merging on every edit. edge_cap >= 32: a cell crossed by a
  // boundary or two must not split (a long slanted boundary would split every cell along it).
  std::uint32_t edge_cap = 64;
  std::uint32_t merge_below = 24;
  std::int64_t min_cell_size = 16;
  // >= 0: a uniform grid (thesis 4.4): the tree is built to this depth at once and never
  // splits or merges; at most max_grid_depth(world, config) (tree_boxes.hpp), the depth at
  // which cells still split given min_cell_size, else InvalidConfig. -1: adaptive.
  int grid_depth = -1;
  // Region streaming (spatial/README.md, "Regions"). >= 0: the tree always splits down to this
  // depth and never merges above it; every node at this depth is a region, which can be saved,
  // unloaded (a stub keeps its hash, areas and counts) and loaded on its own, and an edit's result
  // in a region depends on that region alone. At most 10 and max_grid_depth(world, config), and
  // at most grid_depth in grid mode, else InvalidConfig. -1: off (no region, as before).
  int region_depth = -1;
  // Ids per region (needs region_depth >= 0): region r hands out ids r * 2^44 + 1, r * 2^44 + 2,
  // ... from a counter kept in its own node, so regions edited apart (by two servers) never hand
  // out one id twice. r is the region's path read as base-4 digits (region_index).
  bool region_ids = false;
};

// Ids per region (LandscapeConfig::region_ids): the region's index in the high bits.
inline constexpr int kRegionIdBits = 44;

// Limits on what one landscape may hold; an edit, a constructor or a load that would pass one
// throws LimitExceeded and changes nothing. A load also reads at most the bytes a world within
// the limits can take (Landscape::load).
struct LandscapeLimits {
  std::size_t max_vertices = std::size_t{1} << 28;        // all polygons together
  std::size_t max_shape_vertices = std::size_t{1} << 24;  // one edit's shape
  // Cells of the tree (inner nodes are fewer: each has at least two children). Above the 4^10
  // cells of the deepest grid; about 250 bytes each when empty.
  std::size_t max_cells = std::size_t{1} << 22;
};

// A polygon of the landscape named by its id and the closed box of its cell, as PolygonView and
// ChangeSet::Added give them (Landscape::remove).
struct PolygonRef {
  PolygonId id = 0;
  Box64 cell;
};

// One polygon of the landscape as polygons_in shows it. The view shares ownership of the cell
// holding the polygon (the tree is immutable and shared, so this costs a reference count, no
// copy): `polygon` stays valid for as long as the view or a copy of it lives, whatever happens
// to the landscape meanwhile, edits and destruction included. (A plain pointer dangled after the
// next edit of the same landscape: issue 27, point 7.)
struct PolygonView {
  PolygonId id = 0;
  Material material = kEmpty;
  std::shared_ptr<const Polygon> polygon;
  Box64 cell;  // the closed box of its cell
};

// One cell of the tree.
struct CellView {
  Box64 box;
  std::uint32_t depth = 0;
  std::size_t polygons = 0, vertices = 0;
};

// One edit of a batch (Landscape::apply_batch, a frame's edits): inside `shape` every material m
// becomes map[m]. `kind` says how it was asked for (what an edit log writes); the map alone
// says what it does. carve, fill, fill_empty and replace are relabels with these maps, as on
// Landscape.
struct Edit {
  enum class Kind : std::uint8_t { kCarve, kFill, kFillEmpty, kReplace, kRelabel };
  Kind kind = Kind::kRelabel;
  ValidSet shape;
  MaterialMap map;

  static Edit carve(ValidSet shape) {
    return {Kind::kCarve, std::move(shape), MaterialMap::uniform(kEmpty)};
  }
  static Edit fill(ValidSet shape, Material m) {
    return {Kind::kFill, std::move(shape), MaterialMap::uniform(m)};
  }
  static Edit fill_empty(ValidSet shape, Material m) {
    return {Kind::kFillEmpty, std::move(shape), MaterialMap().set(kEmpty, m)};
  }
  static Edit replace(ValidSet shape, Material from, Material to) {
    return {Kind::kReplace, std::move(shape), MaterialMap().set(from, to)};
  }
  static Edit relabel(ValidSet shape, const MaterialMap& map) {
    return {Kind::kRelabel, std::move(shape), map};
  }
};

// A polygon set as an edit's shape, validated as every edit validates it: CoordinateOutOfRange
// for a coordinate beyond kCoordBound, InvalidInput (operand kClip) for any other violation.
EDGELAND_EXPORT ValidSet edit_shape(PolygonSet shape);

// What an edit changed.
struct ChangeSet {
  std::vector<PolygonId> removed;  // ids that no longer exist, ascending
  struct Added {
    PolygonId id;
    Material material;
    Polygon polygon;
    Box64 cell;
  };
  std::vector<Added> added;  // by ascending id
  std::vector<Box64> cells;  // the cells whose content is new (leaves after the edit)
  // Twice the change of area per material (exact; sums to 0 over all materials including 0).
  std::vector<std::pair<Material, Int128>> twice_area_delta;
  bool empty() const noexcept { return removed.empty() && added.empty(); }
};

// The material profile along a segment: a place where the material changes.
struct MaterialCrossing {
  Fraction t;           // at from + t (to - from), 0 <= t <= 1 (exact)
  RationalPoint point;  // the same point, exactly
  Point64 rounded;      // round_to_grid(point): the kernel's one rounding
  Material before = kEmpty, after = kEmpty;
  PolygonId polygon = 0;   // the polygon entered (after != 0), else the one left
  std::uint32_t edge = 0;  // its edge crossed: from vertex edge to vertex edge + 1
  Point64 normal;          // that edge's outward normal (dy, -dx): not normalised, exact
};

// What check() found; empty when every invariant holds.
struct LandscapeReport {
  std::vector<std::string> problems;  // one line each, e.g. "cell (0 0 64 64): polygon 3 outside"
  bool ok() const noexcept { return problems.empty(); }
};

// A node of the tree by the child indices from the root down (each below the node's child
// count, split_boxes order): {} is the root. Deltas and region records name nodes so.
using TreePath = std::vector<std::uint8_t>;

// One node as two worlds compare it (Landscape::node_digest, DivergenceSearch).
struct NodeDigest {
  Box64 box;
  std::uint64_t hash = 0;  // the node's hash: its box and its cell's polygons or children's hashes
  bool cell = false;       // a leaf
  bool loaded = true;      // false: an unloaded region, whose hash is known but not its children
  std::vector<std::uint64_t> children;  // the children's hashes (inner nodes)
  friend bool operator==(const NodeDigest&, const NodeDigest&) = default;
};

// What an edit does where it reaches an unloaded region (Landscape::set_unloaded_policy).
enum class UnloadedRegions : std::uint8_t {
  kRefuse,  // throw RegionNotLoaded and change nothing (the default)
  kSkip,    // change the loaded regions only: one of several owners of a world (store/README.md)
};

// A region as a store keeps it without its content (Landscape::region_summary,
// read_region_summary): what its stub holds.
struct RegionSummary {
  TreePath path;
  std::uint64_t world = 0;  // Landscape::world_hash of the world it belongs to
  std::uint64_t hash = 0;   // the region node's hash
  std::size_t polygons = 0, vertices = 0, cells = 0;
  std::uint32_t deepest = 0;         // the largest depth of a cell in it
  PolygonId min_id = 0, max_id = 0;  // the range of its polygons' ids (0, 0: none)
  PolygonId next_id = 0;             // its id counter (region_ids), else 0
  std::vector<std::pair<Material, Int128>> twice_areas;  // solid materials present, ascending
  friend bool operator==(const RegionSummary&, const RegionSummary&) = default;
};

// Which hashes Landscape::apply_delta compares. A client that knows it has diverged turns them
// off to keep applying what it receives while it repairs.
struct DeltaChecks {
  bool base = true;    // the landscape's state hash must be the delta's base hash
  bool result = true;  // the result must come out with the delta's result hash
};

struct LandscapeStats {
  std::size_t polygons = 0, vertices = 0, cells = 0, depth = 0;
  std::size_t bytes = 0;  // memory of the cells and nodes this landscape holds (shared or not)
};

}  // namespace edgeland
