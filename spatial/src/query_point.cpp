// The point query (spatial/README.md, "Queries"): material_at descends to the cell holding the
// point and tests its polygons by the half-open rule.
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "node.hpp"
#include "query_args.hpp"
#include "regions.hpp"

namespace edgeland {

using detail::Node;

Material Landscape::material_at(Point64 p) const {
  detail::require_query_point(p, 0, "point");
  // p + eps (1, eps) lies in the world only if p is in its half-open box.
  if (p.x < s_.world.min.x || p.y < s_.world.min.y || p.x >= s_.world.max.x ||
      p.y >= s_.world.max.y)
    return kEmpty;
  const Node* n = s_.root.get();
  for (detail::require_loaded(*n); !n->is_cell(); detail::require_loaded(*n)) n = &n->child_at(p);
  const PolygonSet& polys = n->polygon_set();
  for (std::size_t i = 0; i < polys.size(); ++i) {
    const Box64& b = n->boxes[i];
    // p + eps (1, eps) is in the closed box only if p.x < max.x and p.y < max.y.
    if (p.x < b.min.x || p.y < b.min.y || p.x >= b.max.x || p.y >= b.max.y) continue;
    if (inside_half_open(p, polys[i])) return n->material(i);
  }
  return kEmpty;
}

}  // namespace edgeland
