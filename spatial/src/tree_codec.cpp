// The tree's encoding (tree_codec.hpp): preorder, an inner node the byte 1 and its children, a
// cell the byte 0 and its polygons (save_format.hpp).
#include "tree_codec.hpp"

#include <algorithm>
#include <string>

#include "cell_split.hpp"
#include "check.hpp"
#include "regions.hpp"
#include "save_format.hpp"

namespace edgeland::detail {
namespace {

namespace format = save_format;

// The deepest a tree can be: a side of at most 2^32 is cut at most 32 times, and a kd-tree
// cuts one side per level.
constexpr std::uint32_t kMaxDepth = 64;

void write_cell(ByteWriter& w, const Node& n) {
  w.u8(format::kCellTag);
  if (n.region_next != 0) w.varint(n.region_next);
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

void write_tree(ByteWriter& w, const Node& n) {
  require_loaded(n);
  if (n.is_cell()) {
    write_cell(w, n);
    return;
  }
  w.u8(format::kInnerTag);
  if (n.region_next != 0) w.varint(n.region_next);
  for (std::uint32_t i = 0; i < n.child_count; ++i) write_tree(w, *n.children[i]);
}

TreeReader::TreeReader(ByteReader& in, const LandscapeConfig& config, const LandscapeLimits& limits,
                       PolygonId next_id, std::size_t cells, std::size_t vertices)
    : in_(in),
      config_(config),
      limits_(limits),
      next_id_(next_id),
      cells_(cells),
      vertices_(vertices) {}

NodePtr TreeReader::read(const Box64& box, std::uint32_t depth, std::uint64_t index) {
  // Not reached by tests: a node at depth 64 has no side longer than 1, so read_inner refuses
  // its split first; the bound stands should the split rule ever change.
  if (depth > kMaxDepth) in_.fail("tree too deep");
  const auto tag = in_.fixed(1);
  if (tag != format::kInnerTag && tag != format::kCellTag) in_.fail("unknown node tag");
  // A region with its own ids: its counter, then what lies below it in its id space.
  const bool own_ids = config_.region_ids && is_region(config_, depth);
  const Region outer = region_;
  if (own_ids) region_ = {index, read_counter(index)};
  const PolygonId counter = own_ids ? region_.counter : 0;
  NodePtr node = tag == format::kInnerTag ? read_inner(box, depth, index, counter)
                                          : read_cell(box, depth, counter);
  region_ = outer;
  return node;
}

PolygonId TreeReader::read_counter(std::uint64_t index) {
  const PolygonId counter = in_.varint();
  if (counter < region_first_id(index) || counter > region_id_end(index))
    in_.fail("id counter " + std::to_string(counter) + " outside region " + std::to_string(index) +
             "'s id space");
  return counter;
}

// Whether the node may be split is known before its children are read, and whether they
// should have been merged as soon as they are.
NodePtr TreeReader::read_inner(const Box64& box, std::uint32_t depth, std::uint64_t index,
                               PolygonId counter) {
  if (!can_split(box, config_)) in_.fail("a cell too small to split is split");
  if (config_.grid_depth >= 0 && static_cast<int>(depth) >= config_.grid_depth)
    in_.fail("a grid node split below the grid depth");
  const std::vector<Box64> boxes = split_boxes(box, config_);
  if (boxes.size() > in_.left() / format::kMinCellBytes) in_.fail("truncated tree");
  std::vector<NodePtr> children;
  children.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i)
    children.push_back(read(boxes[i], depth + 1, index * 4 + i));
  NodePtr node = make_inner(box, depth, children, counter);
  refuse_problems([&](std::vector<std::string>& p) { check_inner(*node, config_, p); });
  return node;
}

NodePtr TreeReader::read_cell(const Box64& box, std::uint32_t depth, PolygonId counter) {
  if (++cells_ > limits_.max_cells)
    throw LimitExceeded(LimitExceeded::Limit::kCells, limits_.max_cells, cells_);
  const std::size_t start = in_.at();
  const std::size_t n = in_.count(format::kMinPolygonBytes);
  PolygonSet polys(n);
  std::vector<RegionLabel> labels(n);
  std::vector<PolygonId> ids(n);
  for (std::size_t i = 0; i < n; ++i) {
    ids[i] = read_id();
    labels[i] = static_cast<RegionLabel>(in_.fixed(1));
    if (labels[i] == 0) in_.fail("a polygon of material 0");
    polys[i] = read_ring();
  }
  LabeledSet content;
  try {
    content.set = ValidSet(std::move(polys));
  } catch (const InvalidInput& e) {
    in_.seek(start);
    in_.fail(std::string("cell content: ") + e.what());
  }
  content.labels = std::move(labels);
  NodePtr cell = make_cell(box, depth, std::move(content), std::move(ids), counter);
  refuse_problems([&](std::vector<std::string>& p) { check_cell_content(*cell, config_, p); });
  return cell;
}

PolygonId TreeReader::read_id() {
  const PolygonId id = in_.varint();
  if (config_.region_ids) {
    if (region_of_id(id) != region_.index || id == 0 || id >= region_.counter)
      in_.fail("polygon id " + std::to_string(id) + " not below its region's counter");
  } else if (id == 0 || id >= next_id_) {
    in_.fail("polygon id " + std::to_string(id) + " not in 1..next id - 1");
  }
  ids_.push_back(id);
  return id;
}

Polygon TreeReader::read_ring() {
  const std::size_t m = in_.count(2);  // a vertex is at least two one-byte deltas
  vertices_ += m;
  if (vertices_ > limits_.max_vertices)
    throw LimitExceeded(LimitExceeded::Limit::kVertices, limits_.max_vertices, vertices_);
  Polygon ring(m);
  Point64 prev{0, 0};
  for (Point64& p : ring) {
    const std::int64_t dx = in_.zigzag(), dy = in_.zigzag();
    if (!coord_in_range(dx / 2) || !coord_in_range(dy / 2)) in_.fail("coordinate beyond the bound");
    p = {prev.x + dx, prev.y + dy};
    if (!in_range(p)) in_.fail("coordinate beyond the bound");
    prev = p;
  }
  return ring;
}

template <class Check>
void TreeReader::refuse_problems(Check&& check) {
  std::vector<std::string> problems;
  check(problems);
  if (!problems.empty()) in_.fail("invalid world: " + problems.front());
}

void TreeReader::check_ids() {
  std::sort(ids_.begin(), ids_.end());
  const auto twice = std::adjacent_find(ids_.begin(), ids_.end());
  if (twice != ids_.end()) in_.fail("polygon id " + std::to_string(*twice) + " twice");
}

}  // namespace edgeland::detail
