// The save file (spatial/README.md, "Save/load"): little-endian, varints for counts and
// coordinate deltas, an FNV-1a-64 checksum at the end. load() trusts nothing: every count is
// bounded by the bytes left before anything is allocated, and the world it builds must pass
// every invariant (check.cpp) before it is returned.
#include <istream>
#include <ostream>
#include <set>

#include "cell_split.hpp"
#include "check.hpp"
#include "edgeland/kernel/area.hpp"
#include "landscape_access.hpp"
#include "node.hpp"

namespace edgeland {
namespace {

constexpr char kMagic[8] = {'E', 'D', 'G', 'E', 'L', 'A', 'N', 'D'};
constexpr std::uint32_t kVersion = 1;
constexpr std::uint32_t kMaxDepth = 64;

std::uint64_t fnv1a64(const std::string& bytes, std::size_t n) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::size_t i = 0; i < n; ++i) {
    h ^= static_cast<unsigned char>(bytes[i]);
    h *= 0x100000001b3ull;
  }
  return h;
}

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

void write_node(Writer& w, const detail::Node& n) {
  if (!n.is_cell()) {
    w.u8(1);
    for (std::uint32_t i = 0; i < n.child_count; ++i) write_node(w, *n.children[i]);
    return;
  }
  w.u8(0);
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

}  // namespace

class LandscapeLoader {
 public:
  LandscapeLoader(std::string bytes, const LandscapeLimits& limits)
      : bytes_(std::move(bytes)), limits_(limits) {}

  Landscape load() {
    if (bytes_.size() < sizeof(kMagic) + 4 + 8) fail("file too short for a landscape");
    if (bytes_.compare(0, sizeof(kMagic), kMagic, sizeof(kMagic)) != 0)
      fail("not a landscape save file");
    end_ = bytes_.size();
    at_ = end_ - 8;
    const std::uint64_t checksum = fixed(8);
    end_ -= 8;
    if (checksum != fnv1a64(bytes_, end_)) fail("checksum mismatch: the file is corrupt");
    at_ = sizeof(kMagic);
    if (const auto v = fixed(4); v != kVersion) fail("unsupported version " + std::to_string(v));
    detail::LandscapeState st;
    read_config(st);
    st.limits = limits_;
    st.root = read_node(st.world, 0, st.config);
    if (at_ != end_) fail("bytes left after the tree");
    st.next_id = next_id_;
    auto areas = std::make_shared<detail::AreaTable>();
    detail::for_each_cell(st.root, [&](const detail::NodePtr& c) {
      for (std::size_t i = 0; i < c->ids.size(); ++i)
        (*areas)[c->content.labels[i]] += twice_signed_area(c->polygon_set()[i]);
    });
    st.areas = std::move(areas);
    if (st.root->vertices > limits_.max_vertices) fail("more vertices than the limit");
    st.edits = 1;  // its log is not known: a recording starts from its state
    Landscape l = LandscapeAccess::make(std::move(st));
    const LandscapeReport report = detail::check_all(l);
    if (!report.ok()) fail("invalid world: " + report.problems.front());
    return l;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw LoadError(what, at_); }

  std::uint64_t fixed(int n) {
    if (end_ - at_ < static_cast<std::size_t>(n)) fail("truncated");
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i)
      v |= std::uint64_t{static_cast<unsigned char>(bytes_[at_ + i])} << (8 * i);
    at_ += static_cast<std::size_t>(n);
    return v;
  }
  std::uint64_t varint() {
    std::uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      const std::uint64_t b = fixed(1);
      if (shift == 63 && b > 1) fail("varint overflows 64 bits");
      v |= (b & 0x7f) << shift;
      if (!(b & 0x80)) return v;
    }
    fail("varint longer than 10 bytes");
  }
  std::int64_t zigzag() {
    const std::uint64_t v = varint();
    return static_cast<std::int64_t>(v >> 1) ^ -static_cast<std::int64_t>(v & 1);
  }
  std::int64_t coordinate() {
    const auto c = static_cast<std::int64_t>(fixed(8));
    if (!coord_in_range(c)) fail("coordinate beyond the bound");
    return c;
  }
  // A count of items of at least `min_bytes` each, bounded by the bytes left.
  std::size_t count(std::size_t min_bytes) {
    const std::uint64_t n = varint();
    if (n > (end_ - at_) / min_bytes) fail("count larger than the file");
    return static_cast<std::size_t>(n);
  }

  void read_config(detail::LandscapeState& l) {
    LandscapeConfig& c = l.config;
    const auto tree = fixed(1);
    if (tree > 1) fail("unknown tree kind");
    c.tree = static_cast<TreeKind>(tree);
    c.edge_cap = static_cast<std::uint32_t>(fixed(4));
    c.merge_below = static_cast<std::uint32_t>(fixed(4));
    c.min_cell_size = static_cast<std::int64_t>(fixed(8));
    c.grid_depth = static_cast<int>(static_cast<std::int32_t>(fixed(4)));
    l.world.min.x = coordinate();
    l.world.min.y = coordinate();
    l.world.max.x = coordinate();
    l.world.max.y = coordinate();
    next_id_ = fixed(8);
    try {
      detail::require_config(l.world, c);
    } catch (const InvalidConfig& e) {
      fail(e.what());
    }
  }

  detail::NodePtr read_node(const Box64& box, std::uint32_t depth, const LandscapeConfig& config) {
    if (depth > kMaxDepth) fail("tree too deep");
    const auto tag = fixed(1);
    if (tag == 1) {
      if (!detail::can_split(box, config)) fail("a cell too small to split is split");
      std::vector<detail::NodePtr> children;
      for (const Box64& b : detail::split_boxes(box, config))
        children.push_back(read_node(b, depth + 1, config));
      return detail::make_inner(box, depth, children);
    }
    if (tag != 0) fail("unknown node tag");
    return read_cell(box, depth);
  }

  detail::NodePtr read_cell(const Box64& box, std::uint32_t depth) {
    const std::size_t start = at_;
    const std::size_t n = count(4);  // id, material, vertex count, >= 1 vertex byte pair
    PolygonSet polys(n);
    std::vector<RegionLabel> labels(n);
    std::vector<PolygonId> ids(n);
    for (std::size_t i = 0; i < n; ++i) {
      ids[i] = varint();
      if (ids[i] == 0 || ids[i] >= next_id_ || !seen_ids_.insert(ids[i]).second)
        fail("bad or repeated polygon id");
      labels[i] = static_cast<RegionLabel>(fixed(1));
      if (labels[i] == 0) fail("a polygon of material 0");
      const std::size_t m = count(2);
      vertices_ += m;
      if (vertices_ > limits_.max_vertices) fail("more vertices than the limit");
      polys[i].resize(m);
      Point64 prev{0, 0};
      for (Point64& p : polys[i]) {
        const std::int64_t dx = zigzag(), dy = zigzag();
        if (!coord_in_range(dx / 2) || !coord_in_range(dy / 2)) fail("coordinate beyond the bound");
        p = {prev.x + dx, prev.y + dy};
        if (!in_range(p)) fail("coordinate beyond the bound");
        prev = p;
      }
    }
    LabeledSet content;
    try {
      content.set = ValidSet(std::move(polys));
    } catch (const InvalidInput& e) {
      at_ = start;
      fail(std::string("cell content: ") + e.what());
    }
    content.labels = std::move(labels);
    return detail::make_cell(box, depth, std::move(content), std::move(ids));
  }

  std::string bytes_;
  LandscapeLimits limits_;
  std::size_t at_ = 0, end_ = 0;
  PolygonId next_id_ = 1;
  std::set<PolygonId> seen_ids_;
  std::size_t vertices_ = 0;
};

void Landscape::save(std::ostream& out) const {
  Writer w;
  for (char c : kMagic) w.u8(static_cast<std::uint8_t>(c));
  w.fixed(kVersion, 4);
  const LandscapeConfig& c = s_.config;
  w.fixed(static_cast<std::uint64_t>(c.tree), 1);
  w.fixed(c.edge_cap, 4);
  w.fixed(c.merge_below, 4);
  w.fixed(static_cast<std::uint64_t>(c.min_cell_size), 8);
  w.fixed(static_cast<std::uint32_t>(c.grid_depth), 4);
  for (std::int64_t v : {s_.world.min.x, s_.world.min.y, s_.world.max.x, s_.world.max.y})
    w.fixed(static_cast<std::uint64_t>(v), 8);
  w.fixed(s_.next_id, 8);
  write_node(w, *s_.root);
  w.fixed(fnv1a64(w.bytes(), w.bytes().size()), 8);
  out.write(w.bytes().data(), static_cast<std::streamsize>(w.bytes().size()));
}

Landscape Landscape::load(std::istream& in, const LandscapeLimits& limits) {
  // Read at most what the limits allow: a vertex takes at least two bytes, a polygon four.
  const std::size_t max_bytes = 64 + limits.max_vertices * 24 + (std::size_t{1} << 20);
  std::string bytes;
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof(buffer));
    bytes.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (bytes.size() > max_bytes)
      throw LoadError("file larger than the limits allow", bytes.size());
  }
  if (in.bad()) throw LoadError("the stream failed", bytes.size());
  return LandscapeLoader(std::move(bytes), limits).load();
}

}  // namespace edgeland
