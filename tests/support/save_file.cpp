#include "save_file.hpp"

namespace edgeland::fuzz {
namespace {

constexpr std::string_view kMagic = "EDGELAND";
constexpr std::size_t kChecksumBytes = 8;

class Out {
 public:
  void fixed(std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) s.push_back(static_cast<char>(v >> (8 * i)));
  }
  void varint(std::uint64_t v) {
    for (; v >= 0x80; v >>= 7) s.push_back(static_cast<char>((v & 0x7f) | 0x80));
    s.push_back(static_cast<char>(v));
  }
  void zigzag(std::int64_t v) {
    varint((static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63));
  }
  std::string s;
};

class In {
 public:
  explicit In(std::string_view bytes) : b_(bytes) {}
  bool done() const { return at_ == b_.size(); }
  std::optional<std::uint64_t> fixed(int bytes) {
    if (b_.size() - at_ < static_cast<std::size_t>(bytes)) return std::nullopt;
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i)
      v |= std::uint64_t{static_cast<unsigned char>(b_[at_++])} << (8 * i);
    return v;
  }
  std::optional<std::uint64_t> varint() {
    std::uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      const auto byte = fixed(1);
      if (!byte) return std::nullopt;
      v |= (*byte & 0x7f) << shift;
      if (!(*byte & 0x80)) return v;
    }
    return std::nullopt;
  }
  std::optional<std::int64_t> zigzag() {
    const auto v = varint();
    if (!v) return std::nullopt;
    return static_cast<std::int64_t>(*v >> 1) ^ -static_cast<std::int64_t>(*v & 1);
  }

 private:
  std::string_view b_;
  std::size_t at_ = 0;
};

bool read_header(In& in, SaveFile& f) {
  const auto version = in.fixed(4), tree = in.fixed(1), cap = in.fixed(4), merge = in.fixed(4),
             min = in.fixed(8), grid = in.fixed(4);
  if (!grid) return false;
  f.version = static_cast<std::uint32_t>(*version);
  f.tree = static_cast<std::uint8_t>(*tree);
  f.edge_cap = static_cast<std::uint32_t>(*cap);
  f.merge_below = static_cast<std::uint32_t>(*merge);
  f.min_cell_size = static_cast<std::int64_t>(*min);
  f.grid_depth = static_cast<std::int32_t>(static_cast<std::uint32_t>(*grid));
  for (std::int64_t& w : f.world) {
    const auto v = in.fixed(8);
    if (!v) return false;
    w = static_cast<std::int64_t>(*v);
  }
  const auto next = in.fixed(8);
  if (!next) return false;
  f.next_id = *next;
  return true;
}

// Counts are capped by what the bytes can hold, so a hostile count allocates nothing.
bool read_cell(In& in, SavedNode& node, std::size_t bytes) {
  const auto count = in.varint();
  if (!count || *count > bytes) return false;
  for (std::uint64_t i = 0; i < *count; ++i) {
    SavedPolygon p;
    const auto id = in.varint(), material = in.fixed(1), vertices = in.varint();
    if (!vertices || *vertices > bytes) return false;
    p.id = *id;
    p.material = static_cast<std::uint8_t>(*material);
    Point64 at{0, 0};
    for (std::uint64_t v = 0; v < *vertices; ++v) {
      const auto dx = in.zigzag(), dy = in.zigzag();
      if (!dy) return false;
      at = {static_cast<std::int64_t>(static_cast<std::uint64_t>(at.x) +
                                      static_cast<std::uint64_t>(*dx)),
            static_cast<std::int64_t>(static_cast<std::uint64_t>(at.y) +
                                      static_cast<std::uint64_t>(*dy))};
      p.ring.push_back(at);
    }
    node.polygons.push_back(std::move(p));
  }
  return true;
}

void full_tree(std::vector<SavedNode>& nodes, int depth) {
  nodes.push_back(SavedNode{depth > 0, {}});
  if (depth > 0)
    for (int i = 0; i < 4; ++i) full_tree(nodes, depth - 1);
}

}  // namespace

std::uint64_t save_checksum(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  return h;
}

std::optional<SaveFile> decode_save(std::string_view bytes) {
  if (bytes.size() < kMagic.size() + kChecksumBytes || bytes.substr(0, kMagic.size()) != kMagic)
    return std::nullopt;
  const std::string_view body =
      bytes.substr(kMagic.size(), bytes.size() - kMagic.size() - kChecksumBytes);
  In in(body);
  SaveFile f;
  if (!read_header(in, f)) return std::nullopt;
  while (!in.done()) {
    const auto tag = in.fixed(1);
    SavedNode node;
    node.inner = *tag == 1;
    if (*tag > 1 || (*tag == 0 && !read_cell(in, node, body.size()))) return std::nullopt;
    f.nodes.push_back(std::move(node));
  }
  return f;
}

std::string encode_save(const SaveFile& f) {
  Out out;
  out.s = std::string(kMagic);
  out.fixed(f.version, 4);
  out.fixed(f.tree, 1);
  out.fixed(f.edge_cap, 4);
  out.fixed(f.merge_below, 4);
  out.fixed(static_cast<std::uint64_t>(f.min_cell_size), 8);
  out.fixed(static_cast<std::uint32_t>(f.grid_depth), 4);
  for (const std::int64_t w : f.world) out.fixed(static_cast<std::uint64_t>(w), 8);
  out.fixed(f.next_id, 8);
  for (const SavedNode& node : f.nodes) {
    out.fixed(node.inner ? 1 : 0, 1);
    if (node.inner) continue;
    out.varint(node.polygons.size());
    for (const SavedPolygon& p : node.polygons) {
      out.varint(p.id);
      out.fixed(p.material, 1);
      out.varint(p.ring.size());
      Point64 prev{0, 0};
      for (const Point64 v : p.ring) {
        out.zigzag(static_cast<std::int64_t>(static_cast<std::uint64_t>(v.x) -
                                             static_cast<std::uint64_t>(prev.x)));
        out.zigzag(static_cast<std::int64_t>(static_cast<std::uint64_t>(v.y) -
                                             static_cast<std::uint64_t>(prev.y)));
        prev = v;
      }
    }
  }
  out.fixed(save_checksum(out.s), 8);
  return out.s;
}

SaveFile full_tree_of_empty_cells(int depth) {
  SaveFile f;
  f.min_cell_size = 1;
  f.world[0] = f.world[1] = -kCoordBound;
  f.world[2] = f.world[3] = kCoordBound;
  full_tree(f.nodes, depth);
  return f;
}

}  // namespace edgeland::fuzz
