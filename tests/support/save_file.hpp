#pragma once
// A landscape save file as its fields (spatial/src/save_format.hpp has the layout), read and
// written without any of load()'s checks: the load fuzzer mutates decoded saves field by field
// and writes them back with a correct checksum (the checksum is no defence: anyone recomputes
// it), and the tests build hostile files from it (issue 27, points 1-4). An independent codec:
// it shares no code with spatial/, so a mistake in the library's reader is not repeated here.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "edgeland/kernel/point.hpp"

namespace edgeland::fuzz {

struct SavedPolygon {
  std::uint64_t id = 1;
  std::uint8_t material = 1;
  std::vector<Point64> ring;  // absolute coordinates (the file stores deltas)
};

// One node of the tree in preorder: an inner node (its children are the nodes that follow) or
// a cell with its polygons.
struct SavedNode {
  bool inner = false;
  std::vector<SavedPolygon> polygons;
};

struct SaveFile {
  std::uint32_t version = 1;
  std::uint8_t tree = 0;  // 0 quadtree, 1 kd-tree
  std::uint32_t edge_cap = 64;
  std::uint32_t merge_below = 24;
  std::int64_t min_cell_size = 16;
  std::int32_t grid_depth = -1;
  std::int64_t world[4] = {0, 0, 1024, 1024};  // min.x min.y max.x max.y
  std::uint64_t next_id = 1;
  std::vector<SavedNode> nodes;
};

// The fields of `bytes`, or nothing when they do not even parse as a sequence of nodes (the
// checksum is not looked at, nor any rule of the tree).
std::optional<SaveFile> decode_save(std::string_view bytes);

// The bytes of `file`, checksum included.
std::string encode_save(const SaveFile& file);

// The FNV-1a 64 checksum a file of these bytes (checksum excluded) must end with.
std::uint64_t save_checksum(std::string_view bytes_before_checksum);

// The amplification file: a full quadtree of empty cells, `depth` levels deep, over the
// whole coordinate range with min_cell_size 1 (0.6 MB at depth 9, 2.4 MB at 10, 9.8 MB at 11).
SaveFile full_tree_of_empty_cells(int depth);

}  // namespace edgeland::fuzz
