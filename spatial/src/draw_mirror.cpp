// DrawMirror (delta.hpp): a thin client's polygons by id, kept from CHANGES deltas.
#include <algorithm>

#include "edgeland/spatial/delta.hpp"

namespace edgeland {

// Checked whole before anything is changed, so a refused delta leaves the mirror as it was.
void DrawMirror::apply(const Delta& d) {
  if (d.header.kind != DeltaKind::kChanges)
    throw DeltaError("a DrawMirror takes CHANGES deltas only", 0);
  for (const PolygonId id : d.removed)
    if (!polygons_.count(id))
      throw DeltaError("removes id " + std::to_string(id) + ", not held", 0);
  for (std::size_t i = 0; i < d.added.size(); ++i) {
    const PolygonId id = d.added[i].id;
    const bool removed_first = std::binary_search(d.removed.begin(), d.removed.end(), id);
    if ((polygons_.count(id) && !removed_first) || (i > 0 && d.added[i - 1].id >= id))
      throw DeltaError("adds id " + std::to_string(id) + " twice", 0);
  }
  for (const PolygonId id : d.removed) {
    const auto it = polygons_.find(id);
    digest_ -= polygon_digest(id, it->second.material, it->second.polygon);
    polygons_.erase(it);
  }
  for (const DrawnPolygon& a : d.added) {
    digest_ += polygon_digest(a.id, a.material, a.polygon);
    polygons_.emplace(a.id, a);
  }
}

}  // namespace edgeland
