#pragma once
// The tree in the landscape's binary formats (save_format.hpp): written in preorder by
// write_tree, read back by TreeReader, which checks every node as soon as it is read (the save
// file's hardened reader, spatial/README.md "Save/load"). Save files, PATCH deltas and region
// records all carry subtrees this way.
#include <cstddef>
#include <vector>

#include "edgeland/spatial/byte_codec.hpp"
#include "edgeland/spatial/types.hpp"
#include "node.hpp"

namespace edgeland::detail {

// The node and everything below it. A region with its own ids writes its counter (a varint)
// after its tag. Throws RegionNotLoaded at a stub.
void write_tree(ByteWriter& out, const Node& node);

// Reads one subtree. Every count is bounded by the bytes left; cells and vertices count against
// the limits from the totals given (what the world holds besides the subtree: LimitExceeded);
// every id must be in 1..next_id - 1, or with ids per region in its region's space below the
// region's counter (read after the region's tag, or given by set_region when the subtree lies
// below its region's node); each node's rules (I1-I5, I8, the grid) are checked as it
// is read, so a bad subtree is refused having built at most the path above the bad node.
// Refusals are ReadFailure.
class TreeReader {
 public:
  TreeReader(ByteReader& in, const LandscapeConfig& config, const LandscapeLimits& limits,
             PolygonId next_id, std::size_t cells = 0, std::size_t vertices = 0);
  // `index`: the node's path as base-4 digits (region_index), for the id spaces.
  NodePtr read(const Box64& box, std::uint32_t depth, std::uint64_t index = 0);
  // The region a subtree below a region's node lies in (region_ids): its index and counter.
  void set_region(std::uint64_t index, PolygonId counter) noexcept { region_ = {index, counter}; }
  // I6 within what was read: no id twice. Leaves ids() sorted.
  void check_ids();
  const std::vector<PolygonId>& ids() const noexcept { return ids_; }

 private:
  NodePtr read_inner(const Box64& box, std::uint32_t depth, std::uint64_t index, PolygonId counter);
  NodePtr read_cell(const Box64& box, std::uint32_t depth, PolygonId counter);
  PolygonId read_counter(std::uint64_t index);
  PolygonId read_id();
  Polygon read_ring();
  template <class Check>
  void refuse_problems(Check&& check);

  ByteReader& in_;
  LandscapeConfig config_;
  LandscapeLimits limits_;
  PolygonId next_id_;
  struct Region {
    std::uint64_t index = 0;
    PolygonId counter = 0;
  } region_;
  std::size_t cells_, vertices_;
  std::vector<PolygonId> ids_;
};

}  // namespace edgeland::detail
