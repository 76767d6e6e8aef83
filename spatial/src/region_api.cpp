// Regions of a landscape (landscape.hpp "regions"; spatial/README.md "Regions"): listing them,
// their summaries and records, stubs in their place and records back into the stubs, and a
// world of stubs from summaries.
#include <istream>
#include <map>
#include <ostream>

#include "cell_split.hpp"
#include "edgeland/spatial/byte_codec.hpp"
#include "edgeland/spatial/delta.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "region_record.hpp"
#include "regions.hpp"
#include "save_load.hpp"
#include "state_hash.hpp"
#include "tree_codec.hpp"
#include "tree_paths.hpp"

namespace edgeland {
namespace {

using detail::NodePtr;

NodePtr region_or_throw(const detail::LandscapeState& s, const TreePath& path) {
  NodePtr region = detail::region_at(s.root, s.config, path);
  if (!region) throw InvalidPath(path);
  return region;
}

void meeting(const NodePtr& n, const Box64& box, std::uint32_t depth, TreePath& path,
             std::vector<TreePath>& out) {
  if (!n->box.overlaps_open(box)) return;
  if (n->depth == depth) {
    out.push_back(path);
    return;
  }
  for (std::uint32_t i = 0; i < n->child_count; ++i) {
    path.push_back(static_cast<std::uint8_t>(i));
    meeting(n->children[i], box, depth, path, out);
    path.pop_back();
  }
}

std::size_t node_bytes(const NodePtr& root) {
  std::size_t bytes = 0;
  std::vector<const detail::Node*> stack{root.get()};
  while (!stack.empty()) {
    const detail::Node* n = stack.back();
    stack.pop_back();
    bytes += sizeof(detail::Node);
    if (n->stub) bytes += sizeof(detail::StubInfo) + n->stub->twice_areas.capacity() * 32;
    for (std::uint32_t i = 0; i < n->child_count; ++i) stack.push_back(n->children[i].get());
    const PolygonSet& polys = n->polygon_set();
    bytes += polys.capacity() * sizeof(Polygon) + n->ids.capacity() * sizeof(PolygonId) +
             n->boxes.capacity() * sizeof(Box64) +
             n->content.labels.capacity() * sizeof(RegionLabel);
    for (const Polygon& p : polys) bytes += p.capacity() * sizeof(Point64);
  }
  return bytes;
}

// A record's subtree read into the stub at its path: every node checked as load() checks it,
// then its summary compared with the record's and the stub's.
class RegionLoader {
 public:
  RegionLoader(const detail::LandscapeState& s, std::uint64_t world_hash)
      : s_(s), world_hash_(world_hash) {}

  NodePtr read(std::string_view bytes, TreePath& path) {
    const detail::RegionRecord record = detail::read_region_record(bytes);
    const RegionSummary& want = record.summary;
    ByteReader in(bytes, record.subtree_at, record.subtree_end);
    if (want.world != world_hash_) in.fail("a region of another world");
    const NodePtr stub = detail::region_at(s_.root, s_.config, want.path);
    if (!stub) in.fail("its path names no region of this world");
    if (!stub->is_stub()) in.fail("the region is loaded already");
    if (detail::summarize(stub, want.path, world_hash_) != want)
      in.fail("another version of the region than its stub");
    const detail::Node& root = *s_.root;
    detail::TreeReader tree(in, s_.config, s_.limits, s_.next_id, root.cells - stub->cells,
                            root.vertices - stub->vertices);
    NodePtr region = tree.read(stub->box, stub->depth, detail::region_index(want.path));
    if (!in.done()) in.fail("bytes left after the region");
    tree.check_ids();
    if (detail::summarize(region, want.path, world_hash_) != want)
      in.fail("the region's content does not have its summary");
    path = want.path;
    return region;
  }

 private:
  const detail::LandscapeState& s_;
  std::uint64_t world_hash_;
};

}  // namespace

std::vector<TreePath> Landscape::region_paths() const {
  std::vector<TreePath> out;
  for (const detail::RegionRef& r : detail::regions_of(s_.root, s_.config)) out.push_back(r.path);
  return out;
}

std::vector<TreePath> Landscape::regions_meeting(const Box64& box) const {
  std::vector<TreePath> out;
  if (!detail::regions_on(s_.config)) return out;
  TreePath path;
  meeting(s_.root, box, static_cast<std::uint32_t>(s_.config.region_depth), path, out);
  return out;
}

RegionSummary Landscape::region_summary(const TreePath& path) const {
  return detail::summarize(region_or_throw(s_, path), path, world_hash());
}

bool Landscape::region_loaded(const TreePath& path) const {
  return !region_or_throw(s_, path)->is_stub();
}

std::size_t Landscape::region_bytes(const TreePath& path) const {
  return node_bytes(region_or_throw(s_, path));
}

void Landscape::save_region(const TreePath& path, std::ostream& out) const {
  const NodePtr region = region_or_throw(s_, path);
  detail::require_loaded(*region);
  const std::string bytes =
      detail::write_region_record(*region, detail::summarize(region, path, world_hash()));
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

void Landscape::save_region_summary(const TreePath& path, std::ostream& out) const {
  const std::string bytes = detail::write_summary_record(
      detail::summarize(region_or_throw(s_, path), path, world_hash()));
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

void Landscape::unload_region(const TreePath& path) {
  const NodePtr region = region_or_throw(s_, path);
  if (region->is_stub()) return;
  NodePtr stub =
      detail::make_stub(region->box, region->depth, detail::summarize(region, path, world_hash()));
  s_.root = detail::replace_node(detail::nodes_on(s_.root, path), path, std::move(stub));
}

void Landscape::load_region(std::istream& in) {
  const std::string bytes = detail::read_stream(in, s_.limits);
  TreePath path;
  NodePtr region;
  try {
    region = RegionLoader(s_, world_hash()).read(bytes, path);
  } catch (const ReadFailure& failure) {
    throw LoadError(failure.what, failure.offset);
  }
  s_.root = detail::replace_node(detail::nodes_on(s_.root, path), path, std::move(region));
}

RegionSummary Landscape::read_region_summary(std::istream& in) {
  const std::string bytes = detail::read_stream(in, LandscapeLimits{});
  try {
    return detail::read_region_record(bytes).summary;
  } catch (const ReadFailure& failure) {
    throw LoadError(failure.what, failure.offset);
  }
}

}  // namespace edgeland

namespace edgeland {
namespace {

struct PathLess {
  bool operator()(const TreePath& a, const TreePath& b) const { return path_less(a, b); }
};

// The tree above the regions, every region a stub made from its summary.
class StubWorld {
 public:
  StubWorld(const LandscapeConfig& config, std::uint64_t world_hash,
            const std::vector<RegionSummary>& regions)
      : config_(config) {
    for (const RegionSummary& r : regions) {
      if (r.world != world_hash) refuse(r.path, "a region of another world");
      if (!by_path_.emplace(r.path, &r).second) refuse(r.path, "a region given twice");
    }
  }

  NodePtr build(const Box64& box, std::uint32_t depth, TreePath& path) {
    if (detail::is_region(config_, depth)) return stub(box, depth, path);
    const std::vector<Box64> boxes = detail::split_boxes(box, config_);
    std::vector<NodePtr> children;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      path.push_back(static_cast<std::uint8_t>(i));
      children.push_back(build(boxes[i], depth + 1, path));
      path.pop_back();
    }
    return detail::make_inner(box, depth, children);
  }

  void require_all_used() const {
    if (used_ != by_path_.size()) refuse({}, "a region that is no region of this world");
  }

 private:
  NodePtr stub(const Box64& box, std::uint32_t depth, const TreePath& path) {
    const auto it = by_path_.find(path);
    if (it == by_path_.end()) refuse(path, "a region missing");
    const RegionSummary& r = *it->second;
    const std::uint64_t index = detail::region_index(path);
    const bool counter_ok = config_.region_ids ? r.next_id >= detail::region_first_id(index) &&
                                                     r.next_id <= detail::region_id_end(index)
                                               : r.next_id == 0;
    if (!counter_ok || r.cells == 0 || r.deepest < depth) refuse(path, "an impossible summary");
    ++used_;
    return detail::make_stub(box, depth, r);
  }

  [[noreturn]] static void refuse(const TreePath& path, const std::string& what) {
    std::string p;
    for (const std::uint8_t i : path) p += std::to_string(i);
    throw LoadError("region {" + p + "}: " + what, 0);
  }

  const LandscapeConfig& config_;
  std::map<TreePath, const RegionSummary*, PathLess> by_path_;
  std::size_t used_ = 0;
};

}  // namespace

Landscape Landscape::from_regions(const Box64& world, const LandscapeConfig& config,
                                  PolygonId next_id, const std::vector<RegionSummary>& regions,
                                  const LandscapeLimits& limits) {
  detail::require_config(world, config);
  if (!detail::regions_on(config))
    throw InvalidConfig(InvalidConfig::Setting::kRegionDepth, world, config);
  detail::LandscapeState s;
  s.world = world;
  s.config = config;
  s.limits = limits;
  s.next_id = next_id;
  s.edits = 1;  // its log is not known (as after load)
  detail::StateHash world_hash;
  detail::add_world(world_hash, world, config);
  StubWorld stubs(config, world_hash.value(), regions);
  TreePath path;
  s.root = stubs.build(world, 0, path);
  stubs.require_all_used();
  auto areas = std::make_shared<detail::AreaTable>();
  PolygonId max_id = 0;
  for (const RegionSummary& r : regions) {
    for (const auto& [m, a] : r.twice_areas) (*areas)[m.value()] += a;
    max_id = std::max(max_id, r.max_id);
  }
  if (next_id == 0 || (!config.region_ids && max_id >= next_id))
    throw LoadError("next id " + std::to_string(next_id) + " not above every region's ids", 0);
  if (s.root->cells > limits.max_cells)
    throw LimitExceeded(LimitExceeded::Limit::kCells, limits.max_cells, s.root->cells);
  if (s.root->vertices > limits.max_vertices)
    throw LimitExceeded(LimitExceeded::Limit::kVertices, limits.max_vertices, s.root->vertices);
  s.areas = std::move(areas);
  return Landscape(std::move(s));
}

}  // namespace edgeland
