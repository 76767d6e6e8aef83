#include "ids.hpp"

#include <algorithm>
#include <limits>

#include "edgeland/spatial/errors.hpp"

namespace edgeland::detail {

IdSource::IdSource(const NodePtr& old) {
  for_each_cell(old, [&](const NodePtr& cell) {
    const PolygonSet& polys = cell->polygon_set();
    for (std::size_t i = 0; i < polys.size(); ++i)
      entries_.push_back({&polys[i], cell->content.labels[i], cell->ids[i]});
  });
  // A valid landscape holds no two equal rings (disjoint interiors), so the order is total.
  std::sort(entries_.begin(), entries_.end(),
            [](const Entry& a, const Entry& b) { return *a.ring < *b.ring; });
}

PolygonId IdSource::find(const Polygon& ring, RegionLabel material) const {
  auto it = std::lower_bound(entries_.begin(), entries_.end(), ring,
                             [](const Entry& e, const Polygon& r) { return *e.ring < r; });
  if (it == entries_.end() || *it->ring != ring || it->material != material) return 0;
  return it->id;
}

std::vector<PolygonId> match_ids(const IdSource& previous, const LabeledSet& content,
                                 PolygonId& next_id, PolygonId end) {
  const PolygonSet& polys = content.set.polygons();
  std::vector<PolygonId> ids(polys.size());
  for (std::size_t i = 0; i < polys.size(); ++i) {
    const PolygonId kept = previous.find(polys[i], content.labels[i]);
    if (kept != 0) {
      ids[i] = kept;
      continue;
    }
    // Only a crafted save file can bring the counter here; a wrapped id would repeat id 0.
    if (next_id == end) throw LimitExceeded(LimitExceeded::Limit::kPolygonIds, end, end);
    ids[i] = next_id++;
  }
  return ids;
}

}  // namespace edgeland::detail
