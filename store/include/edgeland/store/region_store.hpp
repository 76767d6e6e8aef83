#pragma once
// The interface every region store keeps (store/README.md): a table of region records keyed by
// region path, and the world's own row, written only in transactions.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "edgeland/kernel/export.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "edgeland/store/errors.hpp"

namespace edgeland::store {

// The world's own row: what a world of stubs is made from besides its regions. Stored as columns
// (store/README.md) and checked by Landscape::from_regions when a world is opened.
struct WorldRecord {
  Box64 world;
  LandscapeConfig config;
  PolygonId next_id = 1;
  std::uint64_t seq = 0;  // the edit sequence number of the last commit
};

// One row of the regions table.
struct StoredRegion {
  TreePath path;
  std::string record;      // Landscape::save_region's bytes
  std::uint64_t hash = 0;  // the region's hash (the record's)
  std::uint64_t seq = 0;   // the edit sequence number it was written at
};

class EDGELAND_EXPORT RegionStore {
 public:
  virtual ~RegionStore() = default;
  // The world's row, if one was ever committed.
  virtual std::optional<WorldRecord> world() = 0;
  virtual std::optional<StoredRegion> region(const TreePath& path) = 0;
  // Every region row, one at a time (memory: one record), in path order.
  virtual void for_each_region(const std::function<void(const StoredRegion&)>& visit) = 0;
  // One transaction: every region (a row is replaced only by a record of a later or equal
  // sequence number) and the world's row when given. Throws StoreError, and then nothing of it
  // is stored.
  virtual void commit(const std::vector<StoredRegion>& regions,
                      const std::optional<WorldRecord>& world) = 0;
};

// The row of a loaded region of `world`, written at `seq`.
EDGELAND_EXPORT StoredRegion stored_region(const Landscape& world, const TreePath& path,
                                           std::uint64_t seq);
// Writes a whole world (every region loaded) at `seq`, with its world row, in one transaction.
EDGELAND_EXPORT void write_world(RegionStore& store, const Landscape& world, std::uint64_t seq);
// The world a store holds, every region a stub (Landscape::from_regions), in one pass over the
// rows; `seqs`, when given, receives each region's sequence number. Throws StoreError (no world
// row), LoadError (a damaged record, a region missing) or LimitExceeded.
EDGELAND_EXPORT Landscape open_world(RegionStore& store, const LandscapeLimits& limits = {},
                                     std::map<TreePath, std::uint64_t>* seqs = nullptr);

// The world row's columns, in the order of both stores' tables, and back.
EDGELAND_EXPORT std::array<std::int64_t, 13> world_columns(const WorldRecord& record);
EDGELAND_EXPORT WorldRecord world_of_columns(const std::array<std::int64_t, 13>& columns);
// Loads one region of `world` from the store. Throws StoreError (no such row) or what
// Landscape::load_region throws.
EDGELAND_EXPORT void load_region(RegionStore& store, Landscape& world, const TreePath& path);

}  // namespace edgeland::store
