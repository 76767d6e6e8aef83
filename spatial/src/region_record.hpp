#pragma once
// The region record (spatial/README.md, "Regions"): one region of a landscape with its summary,
// what Landscape::save_region writes and load_region reads. Little-endian, varints as in the
// save file:
//   magic "EDGEREGN", version u32, world hash u64, path (length varint, one byte a level),
//   hash u64, polygons, vertices, cells, deepest, min id, max id, id counter (varints), the areas
//   (count varint; per solid material present, ascending: material u8, twice the area as a
//   two's-complement 128-bit integer, low u64 then high u64), the region's subtree (the save
//   file's tree encoding), FNV-1a 64 of everything before it.
#include <cstddef>
#include <string>
#include <string_view>

#include "edgeland/spatial/types.hpp"
#include "node.hpp"

namespace edgeland::detail {

std::string write_region_record(const Node& region, const RegionSummary& summary);
// A record of the summary alone (no subtree): what a stub is made from. load_region refuses it.
std::string write_summary_record(const RegionSummary& summary);

// The summary of a record and where its subtree lies in it, the checksum checked. Throws
// ReadFailure.
struct RegionRecord {
  RegionSummary summary;
  std::size_t subtree_at = 0, subtree_end = 0;
};
RegionRecord read_region_record(std::string_view bytes);

}  // namespace edgeland::detail
