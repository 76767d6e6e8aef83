// The tree seen from outside, node by node (delta.hpp): digests for finding where two worlds
// differ, subtrees as PATCH entries, and the digest of what a thin client draws.
#include "edgeland/spatial/byte_codec.hpp"
#include "edgeland/spatial/delta.hpp"
#include "regions.hpp"
#include "state_hash.hpp"
#include "tree_codec.hpp"
#include "tree_paths.hpp"

namespace edgeland {
namespace {

detail::NodePtr node_or_throw(const detail::NodePtr& root, const TreePath& path) {
  const std::vector<detail::NodePtr> chain = detail::nodes_on(root, path);
  if (chain.empty()) throw InvalidPath(path);
  return chain.back();
}

}  // namespace

std::uint64_t polygon_digest(PolygonId id, Material material, const Polygon& polygon) noexcept {
  detail::StateHash h;
  h.add(static_cast<std::uint64_t>(id)).add(static_cast<std::uint64_t>(material.value()));
  h.add(static_cast<std::uint64_t>(polygon.size()));
  for (Point64 p : polygon) h.add(p);
  return h.value();
}

std::optional<NodeDigest> Landscape::node_digest(const TreePath& path) const {
  const std::vector<detail::NodePtr> chain = detail::nodes_on(s_.root, path);
  if (chain.empty()) return std::nullopt;
  const detail::Node& n = *chain.back();
  NodeDigest d{n.box, n.hash, n.is_cell(), !n.is_stub(), {}};
  for (std::uint32_t i = 0; i < n.child_count; ++i) d.children.push_back(n.children[i]->hash);
  return d;
}

PatchEntry Landscape::patch_entry(const TreePath& path) const {
  const detail::NodePtr n = node_or_throw(s_.root, path);
  ByteWriter w;
  detail::write_tree(w, *n);
  // Below a region with its own ids, the region's counter travels with the subtree.
  const auto depth = static_cast<std::size_t>(std::max(s_.config.region_depth, 0));
  PolygonId counter = 0;
  if (s_.config.region_ids && path.size() > depth)
    counter =
        detail::nodes_on(s_.root, TreePath(path.begin(), path.begin() + depth)).back()->region_next;
  return PatchEntry{path, n->hash, counter, std::move(w.bytes())};
}

std::uint64_t Landscape::drawn_digest(const TreePath& path) const {
  const detail::NodePtr n = node_or_throw(s_.root, path);
  std::uint64_t sum = 0;
  detail::for_each_node(n, [&](const detail::NodePtr& c) {
    detail::require_loaded(*c);
    if (!c->is_cell()) return;
    for (std::size_t i = 0; i < c->ids.size(); ++i)
      sum += polygon_digest(c->ids[i], c->material(i), c->polygon_set()[i]);
  });
  return sum;
}

}  // namespace edgeland
