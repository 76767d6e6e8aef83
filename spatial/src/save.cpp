// Landscape::save (save_state): the tree in preorder, polygons as zigzag varint deltas
// (save_format.hpp).
#include <ostream>
#include <string>

#include "edgeland/spatial/landscape.hpp"
#include "node.hpp"
#include "save_format.hpp"
#include "save_load.hpp"

namespace edgeland {
namespace {

namespace format = detail::save_format;

class Writer {
 public:
  void u8(std::uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void fixed(std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) u8(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void varint(std::uint64_t v) {
    while (v >= 0x80) {
      u8(static_cast<std::uint8_t>(v | 0x80));
      v >>= 7;
    }
    u8(static_cast<std::uint8_t>(v));
  }
  void zigzag(std::int64_t v) {
    varint((static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63));
  }
  std::string& bytes() { return out_; }

 private:
  std::string out_;
};

void write_header(Writer& w, const detail::LandscapeState& s) {
  for (char c : format::kMagic) w.u8(static_cast<std::uint8_t>(c));
  w.fixed(format::kVersion, 4);
  const LandscapeConfig& c = s.config;
  w.fixed(static_cast<std::uint64_t>(c.tree), 1);
  w.fixed(c.edge_cap, 4);
  w.fixed(c.merge_below, 4);
  w.fixed(static_cast<std::uint64_t>(c.min_cell_size), 8);
  w.fixed(static_cast<std::uint32_t>(c.grid_depth), 4);
  for (std::int64_t v : {s.world.min.x, s.world.min.y, s.world.max.x, s.world.max.y})
    w.fixed(static_cast<std::uint64_t>(v), 8);
  w.fixed(s.next_id, 8);
}

void write_cell(Writer& w, const detail::Node& n) {
  w.u8(format::kCellTag);
  const PolygonSet& polys = n.polygon_set();
  w.varint(polys.size());
  for (std::size_t i = 0; i < polys.size(); ++i) {
    w.varint(n.ids[i]);
    w.u8(static_cast<std::uint8_t>(n.content.labels[i]));
    w.varint(polys[i].size());
    Point64 prev{0, 0};
    for (Point64 p : polys[i]) {
      w.zigzag(p.x - prev.x);
      w.zigzag(p.y - prev.y);
      prev = p;
    }
  }
}

void write_node(Writer& w, const detail::Node& n) {
  if (n.is_cell()) {
    write_cell(w, n);
    return;
  }
  w.u8(format::kInnerTag);
  for (std::uint32_t i = 0; i < n.child_count; ++i) write_node(w, *n.children[i]);
}

}  // namespace

void detail::save_state(const LandscapeState& state, std::ostream& out) {
  Writer w;
  write_header(w, state);
  write_node(w, *state.root);
  w.fixed(format::fnv1a64(w.bytes()), 8);
  out.write(w.bytes().data(), static_cast<std::streamsize>(w.bytes().size()));
}

void Landscape::save(std::ostream& out) const { detail::save_state(s_, out); }

}  // namespace edgeland
