#pragma once
// The save file (spatial/README.md, "Save/load"), shared by its writer (save.cpp) and its reader
// (load.cpp). Little-endian:
//   magic "EDGELAND", version u32, tree u8, edge_cap u32, merge_below u32, min_cell_size i64,
//   grid_depth i32, world min.x min.y max.x max.y i64, next_id u64,
//   the tree in preorder: an inner node is the byte 1 (its children follow, split_boxes order);
//   a cell is the byte 0, its polygon count (varint), and per polygon: id (varint), material
//   (u8), vertex count (varint), each vertex as the zigzag varint deltas of x and y from the
//   previous vertex (the first from (0, 0)),
//   FNV-1a 64 of everything before it, u64.
// Version 2 (a landscape with regions, LandscapeConfig::region_depth >= 0; a world without them
// is still written as version 1, byte for byte as before): after grid_depth, region_depth i32 and
// region_ids u8; with region_ids, each region's node writes its id counter (varint) after its
// tag.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace edgeland::detail::save_format {

inline constexpr char kMagic[8] = {'E', 'D', 'G', 'E', 'L', 'A', 'N', 'D'};
inline constexpr std::uint32_t kVersion = 1;
inline constexpr std::uint32_t kRegionsVersion = 2;
inline constexpr std::size_t kRegionHeaderBytes = 4 + 1;
inline constexpr std::uint8_t kCellTag = 0;
inline constexpr std::uint8_t kInnerTag = 1;
// Magic, version, configuration (1 + 4 + 4 + 8 + 4), world, next id.
inline constexpr std::size_t kHeaderBytes = 8 + 4 + 21 + 32 + 8;
inline constexpr std::size_t kChecksumBytes = 8;
// The least bytes a cell takes (its tag and a zero count), and a polygon (id, material, count,
// and three vertices of two one-byte deltas): what a count is checked against before anything
// is allocated for it.
inline constexpr std::size_t kMinCellBytes = 2;
inline constexpr std::size_t kMinPolygonBytes = 3 + 3 * 2;
// The most bytes a vertex and a polygon's own fields take (two and three 10-byte varints, a
// byte), and a node: what a file within the landscape's limits can hold at most.
inline constexpr std::size_t kMaxVertexBytes = 20;
inline constexpr std::size_t kMaxPolygonBytes = 21;
inline constexpr std::size_t kMaxNodeBytes = 11;

inline std::uint64_t fnv1a64(std::string_view bytes) noexcept {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ull;
  }
  return h;
}

}  // namespace edgeland::detail::save_format
