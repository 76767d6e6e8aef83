// Landscape::load (spatial/README.md, "Save/load"). A save file is untrusted, and its work is
// bounded before it is done: every count by the bytes left, the cells and vertices by the
// landscape's limits, and every rule of the tree (I2-I5, I8, the grid's shape) is checked on
// each node as soon as it is read, so a file that breaks one is refused having built at most the
// path above that node, never the whole tree first (issue 27, point 1: a full quadtree of empty
// cells, 0.6 MB, took 117 MB and a second before it was refused). Each cell is validated once,
// as it becomes a ValidSet (I1); the tree is made of the same nodes an edit makes (make_cell,
// make_inner: I4, I7); ids are checked against the next id and against each other (I6). So the
// world returned passes check() without it being run again (the load fuzzer checks that).
#include <algorithm>
#include <istream>
#include <limits>
#include <new>
#include <string>
#include <string_view>

#include "cell_split.hpp"
#include "check.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "node.hpp"
#include "save_format.hpp"
#include "save_load.hpp"

namespace edgeland {
namespace {

namespace format = detail::save_format;
using detail::NodePtr;

// The deepest a tree can be: a side of at most 2^32 is cut at most 32 times, and a kd-tree
// cuts one side per level.
constexpr std::uint32_t kMaxDepth = 64;

class Loader {
 public:
  Loader(std::string_view bytes, const LandscapeLimits& limits) : bytes_(bytes), limits_(limits) {}

  detail::LandscapeState load() {
    try {
      return read_landscape();
    } catch (const std::bad_alloc&) {
      // Not reached by tests: every count is bounded by the file's bytes and the limits before
      // anything is allocated for it, so only a world as large as the memory gets here (the
      // peak memory of a load is measured instead: tests/spatial/memory).
      fail("out of memory: the file describes a world larger than the memory available");
    }
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw LoadError(what, at_); }

  detail::LandscapeState read_landscape() {
    check_envelope();
    detail::LandscapeState st;
    read_header(st);
    st.limits = limits_;
    st.root = read_node(st.world, 0);
    if (at_ != end_) fail("bytes left after the tree");
    check_ids(st.next_id);
    st.areas = areas_of(st.root);
    st.edits = 1;  // its log is not known: a recording starts from its state
    return st;
  }

  // --- the bytes ---------------------------------------------------------------------------
  void check_envelope() {
    if (bytes_.size() < format::kHeaderBytes + format::kChecksumBytes)
      fail("file too short for a landscape");
    if (bytes_.substr(0, sizeof format::kMagic) !=
        std::string_view(format::kMagic, sizeof format::kMagic))
      fail("not a landscape save file");
    end_ = bytes_.size();
    at_ = end_ - format::kChecksumBytes;
    const std::uint64_t checksum = fixed(format::kChecksumBytes);
    end_ -= format::kChecksumBytes;
    at_ = sizeof format::kMagic;
    if (checksum != format::fnv1a64(bytes_.substr(0, end_)))
      fail("checksum mismatch: the file is corrupt");
    if (const auto v = fixed(4); v != format::kVersion)
      fail("unsupported version " + std::to_string(v));
  }

  std::uint64_t fixed(std::size_t n) {
    if (end_ - at_ < n) fail("truncated");
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < n; ++i)
      v |= std::uint64_t{static_cast<unsigned char>(bytes_[at_ + i])} << (8 * i);
    at_ += n;
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
    // Not reached by tests: a tenth byte with its continuation bit is above 1 and refused
    // above, so the loop never runs out; kept so the function visibly ends.
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
  // A count of items of at least `min_bytes` each: bounded by the bytes left before anything
  // is allocated for it.
  std::size_t count(std::size_t min_bytes) {
    const std::uint64_t n = varint();
    if (n > (end_ - at_) / min_bytes) fail("count larger than the file");
    return static_cast<std::size_t>(n);
  }

  // --- the header ----------------------------------------------------------------------------
  void read_header(detail::LandscapeState& st) {
    LandscapeConfig& c = st.config;
    const auto tree = fixed(1);
    if (tree > 1) fail("unknown tree kind");
    c.tree = static_cast<TreeKind>(tree);
    c.edge_cap = static_cast<std::uint32_t>(fixed(4));
    c.merge_below = static_cast<std::uint32_t>(fixed(4));
    c.min_cell_size = static_cast<std::int64_t>(fixed(8));
    c.grid_depth = static_cast<int>(static_cast<std::int32_t>(fixed(4)));
    st.world.min.x = coordinate();
    st.world.min.y = coordinate();
    st.world.max.x = coordinate();
    st.world.max.y = coordinate();
    st.next_id = fixed(8);
    // Ids start at 1: a next id of 0 would hand out id 0, which no polygon may have.
    if (st.next_id == 0) fail("next id 0: ids start at 1");
    next_id_ = st.next_id;
    try {
      detail::require_config(st.world, c);
    } catch (const InvalidConfig& e) {
      fail(e.what());
    }
    config_ = c;
  }

  // --- the tree ------------------------------------------------------------------------------
  NodePtr read_node(const Box64& box, std::uint32_t depth) {
    // Not reached by tests: a node at depth 64 has no side longer than 1, so read_inner refuses
    // its split first; the bound stands should the split rule ever change.
    if (depth > kMaxDepth) fail("tree too deep");
    const auto tag = fixed(1);
    if (tag == format::kInnerTag) return read_inner(box, depth);
    if (tag != format::kCellTag) fail("unknown node tag");
    return read_cell(box, depth);
  }

  // Whether the node may be split is known before its children are read, and whether they
  // should have been merged as soon as they are.
  NodePtr read_inner(const Box64& box, std::uint32_t depth) {
    if (!detail::can_split(box, config_)) fail("a cell too small to split is split");
    if (config_.grid_depth >= 0 && static_cast<int>(depth) >= config_.grid_depth)
      fail("a grid node split below the grid depth");
    const std::vector<Box64> boxes = detail::split_boxes(box, config_);
    if (boxes.size() > (end_ - at_) / format::kMinCellBytes) fail("truncated tree");
    std::vector<NodePtr> children;
    children.reserve(boxes.size());
    for (const Box64& b : boxes) children.push_back(read_node(b, depth + 1));
    NodePtr node = detail::make_inner(box, depth, children);
    refuse_problems([&](std::vector<std::string>& p) { detail::check_inner(*node, config_, p); });
    return node;
  }

  NodePtr read_cell(const Box64& box, std::uint32_t depth) {
    if (++cells_ > limits_.max_cells)
      throw LimitExceeded(LimitExceeded::Limit::kCells, limits_.max_cells, cells_);
    const std::size_t start = at_;
    const std::size_t n = count(format::kMinPolygonBytes);
    PolygonSet polys(n);
    std::vector<RegionLabel> labels(n);
    std::vector<PolygonId> ids(n);
    for (std::size_t i = 0; i < n; ++i) {
      ids[i] = read_id();
      labels[i] = static_cast<RegionLabel>(fixed(1));
      if (labels[i] == 0) fail("a polygon of material 0");
      polys[i] = read_ring();
    }
    LabeledSet content;
    try {
      content.set = ValidSet(std::move(polys));
    } catch (const InvalidInput& e) {
      at_ = start;
      fail(std::string("cell content: ") + e.what());
    }
    content.labels = std::move(labels);
    NodePtr cell = detail::make_cell(box, depth, std::move(content), std::move(ids));
    refuse_problems(
        [&](std::vector<std::string>& p) { detail::check_cell_content(*cell, config_, p); });
    return cell;
  }

  PolygonId read_id() {
    const PolygonId id = varint();
    if (id == 0 || id >= next_id_)
      fail("polygon id " + std::to_string(id) + " not in 1..next id - 1");
    ids_.push_back(id);
    return id;
  }

  Polygon read_ring() {
    const std::size_t m = count(2);  // a vertex is at least two one-byte deltas
    vertices_ += m;
    if (vertices_ > limits_.max_vertices)
      throw LimitExceeded(LimitExceeded::Limit::kVertices, limits_.max_vertices, vertices_);
    Polygon ring(m);
    Point64 prev{0, 0};
    for (Point64& p : ring) {
      const std::int64_t dx = zigzag(), dy = zigzag();
      if (!coord_in_range(dx / 2) || !coord_in_range(dy / 2)) fail("coordinate beyond the bound");
      p = {prev.x + dx, prev.y + dy};
      if (!in_range(p)) fail("coordinate beyond the bound");
      prev = p;
    }
    return ring;
  }

  template <class Check>
  void refuse_problems(Check&& check) {
    std::vector<std::string> problems;
    check(problems);
    if (!problems.empty()) fail("invalid world: " + problems.front());
  }

  // --- the whole -----------------------------------------------------------------------------
  // I6: ids unique (each is below the next id already).
  void check_ids(PolygonId next_id) {
    std::sort(ids_.begin(), ids_.end());
    const auto twice = std::adjacent_find(ids_.begin(), ids_.end());
    if (twice != ids_.end()) fail("polygon id " + std::to_string(*twice) + " twice");
    // Not reached by tests: read_id refuses an id not below the next id as it reads it; this
    // states I6 whole, as check() does.
    if (!ids_.empty() && ids_.back() >= next_id) fail("an id is not below the next id");
  }

  static std::shared_ptr<const detail::AreaTable> areas_of(const NodePtr& root) {
    auto areas = std::make_shared<detail::AreaTable>();
    detail::for_each_cell(root, [&](const NodePtr& c) {
      for (std::size_t i = 0; i < c->ids.size(); ++i)
        (*areas)[c->content.labels[i]] += twice_signed_area(c->polygon_set()[i]);
    });
    return areas;
  }

  std::string_view bytes_;
  LandscapeLimits limits_;
  LandscapeConfig config_;
  std::size_t at_ = 0, end_ = 0;
  PolygonId next_id_ = 1;
  std::vector<PolygonId> ids_;
  std::size_t vertices_ = 0, cells_ = 0;
};

// The most bytes a save file of a world within `limits` can take: no more is read.
std::uint64_t max_file_bytes(const LandscapeLimits& limits) {
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  const auto times = [&](std::uint64_t n, std::uint64_t bytes) {
    return n > kMax / bytes ? kMax : n * bytes;
  };
  const auto plus = [&](std::uint64_t a, std::uint64_t b) { return a > kMax - b ? kMax : a + b; };
  const std::uint64_t nodes = times(limits.max_cells, 2 * format::kMaxNodeBytes);
  const std::uint64_t vertices = times(limits.max_vertices, format::kMaxVertexBytes);
  const std::uint64_t polygons = times(limits.max_vertices / 3, format::kMaxPolygonBytes);
  return plus(plus(nodes, vertices), plus(polygons, format::kHeaderBytes + format::kChecksumBytes));
}

// The stream's bytes, at most the limits' worth. Read in chunks and joined once: a string grown
// by doubling would hold up to three times the file while it moves.
std::string read_bytes(std::istream& in, const LandscapeLimits& limits) {
  const std::uint64_t max_bytes = max_file_bytes(limits);
  std::vector<std::string> chunks;
  std::size_t total = 0;
  try {
    while (in) {
      std::string& chunk = chunks.emplace_back(std::size_t{1} << 16, '\0');
      in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
      chunk.resize(static_cast<std::size_t>(in.gcount()));
      total += chunk.size();
      if (total > max_bytes) throw LoadError("file larger than the limits allow", total);
    }
    std::string bytes;
    bytes.reserve(total);
    for (const std::string& chunk : chunks) bytes += chunk;
    if (in.bad()) throw LoadError("the stream failed", total);
    return bytes;
  } catch (const std::bad_alloc&) {
    // Not reached by tests: the bytes read are bounded by the limits (max_file_bytes); only a
    // file that large for the memory gets here.
    throw LoadError("out of memory reading the file", total);
  }
}

}  // namespace

detail::LandscapeState detail::load_state(std::istream& in, const LandscapeLimits& limits) {
  const std::string bytes = read_bytes(in, limits);
  return Loader(bytes, limits).load();
}

Landscape Landscape::load(std::istream& in, const LandscapeLimits& limits) {
  return Landscape(detail::load_state(in, limits));
}

}  // namespace edgeland
