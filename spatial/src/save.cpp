// Landscape::save (save_state): the header, the tree in preorder (tree_codec.hpp), the checksum
// (save_format.hpp).
#include <ostream>
#include <string>

#include "edgeland/spatial/byte_codec.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "node.hpp"
#include "save_format.hpp"
#include "save_load.hpp"
#include "tree_codec.hpp"

namespace edgeland {
namespace {

namespace format = detail::save_format;

void write_header(ByteWriter& w, const detail::LandscapeState& s) {
  for (char c : format::kMagic) w.u8(static_cast<std::uint8_t>(c));
  const LandscapeConfig& c = s.config;
  const bool regions = c.region_depth >= 0;
  w.fixed(regions ? format::kRegionsVersion : format::kVersion, 4);
  w.fixed(static_cast<std::uint64_t>(c.tree), 1);
  w.fixed(c.edge_cap, 4);
  w.fixed(c.merge_below, 4);
  w.fixed(static_cast<std::uint64_t>(c.min_cell_size), 8);
  w.fixed(static_cast<std::uint32_t>(c.grid_depth), 4);
  if (regions) {
    w.fixed(static_cast<std::uint32_t>(c.region_depth), 4);
    w.u8(c.region_ids ? 1 : 0);
  }
  for (std::int64_t v : {s.world.min.x, s.world.min.y, s.world.max.x, s.world.max.y})
    w.fixed(static_cast<std::uint64_t>(v), 8);
  w.fixed(s.next_id, 8);
}

}  // namespace

void detail::save_state(const LandscapeState& state, std::ostream& out) {
  ByteWriter w;
  write_header(w, state);
  write_tree(w, *state.root);
  w.fixed(format::fnv1a64(w.bytes()), 8);
  out.write(w.bytes().data(), static_cast<std::streamsize>(w.bytes().size()));
}

void Landscape::save(std::ostream& out) const { detail::save_state(s_, out); }

}  // namespace edgeland
