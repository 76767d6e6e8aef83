// Landscape::stats: the counts kept in the root, and the memory of every node and its content.
#include "edgeland/spatial/landscape.hpp"
#include "node.hpp"

namespace edgeland {

using detail::Node;

LandscapeStats Landscape::stats() const {
  LandscapeStats s;
  s.polygons = s_.root->polygons;
  s.vertices = s_.root->vertices;
  s.cells = s_.root->cells;
  s.depth = s_.root->deepest;
  // Memory: every node once, its content's arrays by capacity.
  std::vector<const Node*> stack{s_.root.get()};
  while (!stack.empty()) {
    const Node* n = stack.back();
    stack.pop_back();
    s.bytes += sizeof(Node);
    for (std::uint32_t i = 0; i < n->child_count; ++i) stack.push_back(n->children[i].get());
    const PolygonSet& polys = n->polygon_set();
    s.bytes += polys.capacity() * sizeof(Polygon) + n->ids.capacity() * sizeof(PolygonId) +
               n->boxes.capacity() * sizeof(Box64) +
               n->content.labels.capacity() * sizeof(RegionLabel);
    for (const Polygon& p : polys) s.bytes += p.capacity() * sizeof(Point64);
  }
  return s;
}

}  // namespace edgeland
