#pragma once
// The delta envelope (spatial/README.md, "Deltas, divergence and repair"), shared by its writer
// and its reader (delta_codec.cpp). Little-endian:
//   magic "EDGEDLTA", format version u32, kind u8, algorithm u32, world hash u64, sequence u64,
//   base hash u64, result hash u64, the payload of the kind, FNV-1a 64 of everything before it.
#include <cstddef>
#include <cstdint>

namespace edgeland::detail::delta_format {

inline constexpr char kMagic[8] = {'E', 'D', 'G', 'E', 'D', 'L', 'T', 'A'};
inline constexpr std::uint32_t kVersion = 1;
inline constexpr std::size_t kHeaderBytes = 8 + 4 + 1 + 4 + 4 * 8;
inline constexpr std::size_t kChecksumBytes = 8;
// COMMAND forms: one edit (Landscape's edits, apply_edit), or a frame batch of two or more
// (Landscape::apply_batch: one edit of several steps, rounded once).
inline constexpr std::uint8_t kSingleEdit = 0;
inline constexpr std::uint8_t kBatch = 1;
// Shape coordinates are refused from this magnitude on while reading, so that a sum of deltas
// cannot overflow; anything beyond kCoordBound (but below this) reaches the edit, which refuses
// it with CoordinateOutOfRange as it refuses any shape's.
inline constexpr std::int64_t kMaxShapeCoordinate = std::int64_t{1} << 62;
// The least bytes an item takes: what a count is checked against before anything is allocated.
inline constexpr std::size_t kMinEditBytes = 2;                   // kind, polygon count
inline constexpr std::size_t kMinPolygonBytes = 1;                // a vertex count of 0
inline constexpr std::size_t kMinVertexBytes = 2;                 // two one-byte deltas
inline constexpr std::size_t kMinEntryBytes = 1 + 8 + 1 + 1 + 2;  // path, hash, counter, a cell
inline constexpr std::size_t kMinAddedBytes = 3;                  // id gap, material, vertex count
inline constexpr std::size_t kMaxPathLength = 64;

}  // namespace edgeland::detail::delta_format
