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
#include "edgeland/kernel/area.hpp"
#include "edgeland/spatial/byte_codec.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "node.hpp"
#include "save_format.hpp"
#include "save_load.hpp"
#include "tree_codec.hpp"

namespace edgeland {
namespace {

namespace format = detail::save_format;
using detail::NodePtr;

class Loader {
 public:
  Loader(std::string_view bytes, const LandscapeLimits& limits)
      : bytes_(bytes), in_(bytes, 0, bytes.size()), limits_(limits) {}

  detail::LandscapeState load() {
    try {
      return read_landscape();
    } catch (const ReadFailure& failure) {
      throw LoadError(failure.what, failure.offset);
    } catch (const std::bad_alloc&) {
      // Not reached by tests: every count is bounded by the file's bytes and the limits before
      // anything is allocated for it, so only a world as large as the memory gets here (the
      // peak memory of a load is measured instead: tests/spatial/memory).
      throw LoadError("out of memory: the file describes a world larger than the memory available",
                      in_.at());
    }
  }

 private:
  detail::LandscapeState read_landscape() {
    check_envelope();
    detail::LandscapeState st;
    read_header(st);
    st.limits = limits_;
    detail::TreeReader tree(in_, st.config, limits_, st.next_id);
    st.root = tree.read(st.world, 0);
    if (!in_.done()) in_.fail("bytes left after the tree");
    tree.check_ids();
    st.areas = areas_of(st.root);
    st.edits = 1;  // its log is not known: a recording starts from its state
    return st;
  }

  // --- the bytes ---------------------------------------------------------------------------
  void check_envelope() {
    if (bytes_.size() < format::kHeaderBytes + format::kChecksumBytes)
      in_.fail("file too short for a landscape");
    if (bytes_.substr(0, sizeof format::kMagic) !=
        std::string_view(format::kMagic, sizeof format::kMagic))
      in_.fail("not a landscape save file");
    const std::size_t end = bytes_.size() - format::kChecksumBytes;
    ByteReader tail(bytes_, end, bytes_.size());
    const std::uint64_t checksum = tail.fixed(format::kChecksumBytes);
    in_ = ByteReader(bytes_, sizeof format::kMagic, end);
    if (checksum != format::fnv1a64(bytes_.substr(0, end)))
      in_.fail("checksum mismatch: the file is corrupt");
    version_ = in_.fixed(4);
    if (version_ != format::kVersion && version_ != format::kRegionsVersion)
      in_.fail("unsupported version " + std::to_string(version_));
  }

  std::int64_t coordinate() {
    const auto c = static_cast<std::int64_t>(in_.fixed(8));
    if (!coord_in_range(c)) in_.fail("coordinate beyond the bound");
    return c;
  }

  // --- the header ----------------------------------------------------------------------------
  void read_header(detail::LandscapeState& st) {
    LandscapeConfig& c = st.config;
    const auto tree = in_.fixed(1);
    if (tree > 1) in_.fail("unknown tree kind");
    c.tree = static_cast<TreeKind>(tree);
    c.edge_cap = static_cast<std::uint32_t>(in_.fixed(4));
    c.merge_below = static_cast<std::uint32_t>(in_.fixed(4));
    c.min_cell_size = static_cast<std::int64_t>(in_.fixed(8));
    c.grid_depth = static_cast<int>(static_cast<std::int32_t>(in_.fixed(4)));
    if (version_ == format::kRegionsVersion) read_regions(c);
    st.world.min.x = coordinate();
    st.world.min.y = coordinate();
    st.world.max.x = coordinate();
    st.world.max.y = coordinate();
    st.next_id = in_.fixed(8);
    // Ids start at 1: a next id of 0 would hand out id 0, which no polygon may have.
    if (st.next_id == 0) in_.fail("next id 0: ids start at 1");
    try {
      detail::require_config(st.world, c);
    } catch (const InvalidConfig& e) {
      in_.fail(e.what());
    }
  }

  // Version 2: the region options, which must be on (a world without regions is version 1).
  void read_regions(LandscapeConfig& c) {
    c.region_depth = static_cast<int>(static_cast<std::int32_t>(in_.fixed(4)));
    const auto ids = in_.fixed(1);
    if (ids > 1) in_.fail("region_ids neither 0 nor 1");
    c.region_ids = ids == 1;
    if (c.region_depth < 0) in_.fail("a version 2 file without regions");
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
  ByteReader in_;
  LandscapeLimits limits_;
  std::uint64_t version_ = 0;
};

// The most bytes a save file of a world within `limits` can take: no more is read.
std::uint64_t max_file_bytes(const LandscapeLimits& limits) {
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  const auto times = [&](std::uint64_t n, std::uint64_t bytes) {
    return n > kMax / bytes ? kMax : n * bytes;
  };
  const auto plus = [&](std::uint64_t a, std::uint64_t b) { return a > kMax - b ? kMax : a + b; };
  // A node's tag and count, and a region's id counter (a varint of at most 10 bytes).
  const std::uint64_t nodes = times(limits.max_cells, 2 * (format::kMaxNodeBytes + 10));
  const std::uint64_t vertices = times(limits.max_vertices, format::kMaxVertexBytes);
  const std::uint64_t polygons = times(limits.max_vertices / 3, format::kMaxPolygonBytes);
  return plus(
      plus(nodes, vertices),
      plus(polygons, format::kHeaderBytes + format::kRegionHeaderBytes + format::kChecksumBytes));
}

}  // namespace

// Read in chunks and joined once: a string grown by doubling would hold up to three times the
// file while it moves.
std::string detail::read_stream(std::istream& in, const LandscapeLimits& limits) {
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

detail::LandscapeState detail::load_state(std::istream& in, const LandscapeLimits& limits) {
  const std::string bytes = read_stream(in, limits);
  return Loader(bytes, limits).load();
}

Landscape Landscape::load(std::istream& in, const LandscapeLimits& limits) {
  return Landscape(detail::load_state(in, limits));
}

}  // namespace edgeland
