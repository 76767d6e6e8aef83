#pragma once
// Regions (spatial/README.md, "Regions"; LandscapeConfig::region_depth and region_ids): the nodes
// at the region depth, their indices, id spaces and summaries.
#include <cstdint>
#include <string>
#include <vector>

#include "edgeland/spatial/types.hpp"
#include "node.hpp"

namespace edgeland::detail {

inline bool regions_on(const LandscapeConfig& c) noexcept { return c.region_depth >= 0; }
inline bool is_region(const LandscapeConfig& c, std::uint32_t depth) noexcept {
  return c.region_depth >= 0 && depth == static_cast<std::uint32_t>(c.region_depth);
}

// A region's index: its path read as base-4 digits (below 4^10 = 2^20).
std::uint64_t region_index(const TreePath& path) noexcept;
// The id space of region `index`: ids first_id .. end - 1 (LandscapeConfig::region_ids).
inline PolygonId region_first_id(std::uint64_t index) noexcept {
  return (index << kRegionIdBits) + 1;
}
inline PolygonId region_id_end(std::uint64_t index) noexcept {
  return (index + 1) << kRegionIdBits;
}
inline std::uint64_t region_of_id(PolygonId id) noexcept { return id >> kRegionIdBits; }

// Every region with its path, in tree order.
struct RegionRef {
  TreePath path;
  NodePtr node;
};
std::vector<RegionRef> regions_of(const NodePtr& root, const LandscapeConfig& config);

// The summary of a loaded region or of a stub. O(region) for a loaded one.
RegionSummary summarize(const NodePtr& region, const TreePath& path, std::uint64_t world_hash);

// The region node at `path` (nullptr when the path is not a region's).
NodePtr region_at(const NodePtr& root, const LandscapeConfig& config, const TreePath& path);

// The region holding the point (in the world's half-open box) and its index; node is nullptr
// without regions.
struct RegionHere {
  NodePtr node;
  std::uint64_t index = 0;
};
RegionHere region_above(const NodePtr& root, const LandscapeConfig& config, Point64 p);

// Problems of a region's id counter and of ids found in it (region_ids): the counter in the
// region's id space, each id in that space and below the counter.
void check_region_counter(const Node& region, std::uint64_t index, const std::string& name,
                          std::vector<std::string>& problems);
void check_region_ids(const std::vector<PolygonId>& ids, std::uint64_t index, PolygonId counter,
                      const std::string& name, std::vector<std::string>& problems);

// Throws RegionNotLoaded for a stub.
void require_loaded(const Node& node);

}  // namespace edgeland::detail
