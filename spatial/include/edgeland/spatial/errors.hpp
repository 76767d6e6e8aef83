#pragma once
// The landscape's errors: every one is an edgeland::Error (kernel/errors.hpp) and keeps its data
// in fields. Edits also throw the kernel's InvalidInput / CoordinateOutOfRange for a bad shape.
#include <cstddef>
#include <cstdint>
#include <string>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland {

// Every landscape error is an edgeland::Error; each keeps its data in fields.
class EDGELAND_EXPORT LandscapeError : public Error {
 public:
  using Error::Error;
};

// The world box or the configuration is unusable (inverted or degenerate box, box beyond the
// coordinate bound, edge_cap < 32, merge_below >= edge_cap, min_cell_size < 1, grid_depth
// outside -1..10 or deeper than min_cell_size lets the world split).
// `setting` names the rule broken; `world` is the world box given and `config` the
// configuration, whichever of them is wrong.
class EDGELAND_EXPORT InvalidConfig : public LandscapeError {
 public:
  enum class Setting : std::uint8_t {
    kWorldOutOfRange,       // a corner beyond kCoordBound
    kWorldEmpty,            // width or height not positive (inverted or degenerate)
    kEdgeCap,               // edge_cap below 32
    kMergeBelow,            // merge_below not below edge_cap
    kMinCellSize,           // min_cell_size below 1
    kGridDepth,             // grid_depth outside -1..10
    kTree,                  // not a TreeKind
    kGridDepthBeyondCells,  // grid_depth deeper than min_cell_size lets the world split
                            // (max_grid_depth in tree_boxes.hpp); never silently shallower
    kRegionDepth,           // region_depth outside -1..10, beyond max_grid_depth, or below a
                            // grid's depth
    kRegionIds,             // region_ids without a region_depth
  };
  InvalidConfig(Setting setting, const Box64& world, const LandscapeConfig& config);
  Setting setting;
  Box64 world;
  LandscapeConfig config;
};

// A number given as a material is outside 0..255 (material.hpp: thrown where it becomes a
// Material, before the call it is an argument of). `number` is the value given (saturated to
// the int64 range).
class EDGELAND_EXPORT InvalidMaterial : public LandscapeError {
 public:
  explicit InvalidMaterial(std::int64_t number);
  std::int64_t number;
};

// A LandscapeLimits limit would be passed (`requested` > `maximum`), or the polygon ids are
// used up (kPolygonIds: the next id would pass 2^64 - 1, which only a crafted save file can
// bring about).
class EDGELAND_EXPORT LimitExceeded : public LandscapeError {
 public:
  enum class Limit : std::uint8_t { kVertices, kShapeVertices, kCells, kPolygonIds };
  LimitExceeded(Limit limit, std::size_t maximum, std::size_t requested);
  Limit limit;
  std::size_t maximum;
  std::size_t requested;
};

// Landscape::remove named a polygon the landscape does not hold: no cell with the box `cell`,
// or none with the id `id` in it (it changed since it was named).
class EDGELAND_EXPORT UnknownPolygon : public LandscapeError {
 public:
  UnknownPolygon(PolygonId id, const Box64& cell);
  PolygonId id;
  Box64 cell;
};

// A checked-mode invariant failed: a bug in edgeland. `state` is the landscape before the
// edit as a save file (Landscape::load reads it), `log` an edit log that replays to it (exactly
// when the landscape recorded its log from the start, else approximately: the world and one
// fill per material) followed by the failing edit.
class EDGELAND_EXPORT LandscapeInternalError : public LandscapeError {
 public:
  LandscapeInternalError(const std::string& what, std::string state, std::string log);
  std::string state;
  std::string log;
};

// A save file could not be read: truncated, corrupt, of another version, describing a world
// that breaks an invariant, or too large for the memory available. `offset` is where reading
// stopped (bytes from the start).
class EDGELAND_EXPORT LoadError : public LandscapeError {
 public:
  LoadError(const std::string& what, std::size_t offset);
  std::size_t offset;
};

// A delta's bytes could not be read (delta.hpp): truncated, corrupt, of another format, or
// malformed; or a PATCH's subtree breaks a rule of the world it is applied to. `offset` is where
// reading stopped (bytes from the start of the delta).
class EDGELAND_EXPORT DeltaError : public LandscapeError {
 public:
  DeltaError(const std::string& what, std::size_t offset);
  std::size_t offset;
};

// A well-formed delta that does not fit this landscape: `field` says which value differs,
// `expected` is the delta's and `actual` the landscape's.
class EDGELAND_EXPORT DeltaMismatch : public LandscapeError {
 public:
  enum class Field : std::uint8_t {
    kWorld,      // another world box or configuration (world_hash)
    kAlgorithm,  // a COMMAND written by another algorithm version
    kBase,       // the state hash before is not the delta's base hash
    kResult,     // the result's state hash is not the delta's result hash
    kNodeHash,   // a patched node's hash is not the one the PATCH names
  };
  DeltaMismatch(Field field, std::uint64_t expected, std::uint64_t actual);
  Field field;
  std::uint64_t expected;
  std::uint64_t actual;
};

// A tree path names no node of this landscape (an index past a node's children, or a path
// through a cell). `path` is the path given.
class EDGELAND_EXPORT InvalidPath : public LandscapeError {
 public:
  explicit InvalidPath(TreePath path);
  TreePath path;
};

// An edit or a query reached a region that is not loaded (Landscape::unload_region), or a save
// was asked of a world with one. `path` and `box` name the region.
class EDGELAND_EXPORT RegionNotLoaded : public LandscapeError {
 public:
  RegionNotLoaded(TreePath path, const Box64& box);
  TreePath path;
  Box64 box;
};

}  // namespace edgeland
