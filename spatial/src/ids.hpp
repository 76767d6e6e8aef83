#pragma once
// Polygon ids (spatial/README.md, I6): a polygon keeps its id while it stays the same polygon
// (same ring, same material); every other polygon gets the next fresh id.
#include <limits>
#include <vector>

#include "node.hpp"

namespace edgeland::detail {

// The polygons a new cell may take ids from: those of the old cells its box covers, i.e. all
// cells below the old node in its place (a merge), or the one old cell it lies in (an edit, a
// split). A polygon equal to an old one lies in one of these, whatever the cells did.
class IdSource {
 public:
  // Every polygon of every cell below `old` (old itself when it is a cell). O(n log n).
  explicit IdSource(const NodePtr& old);
  // The id of the polygon equal to (ring, material), or 0 if there is none. O(log n).
  PolygonId find(const Polygon& ring, RegionLabel material) const;

 private:
  struct Entry {
    const Polygon* ring;
    RegionLabel material;
    PolygonId id;
  };
  std::vector<Entry> entries_;  // sorted by ring
};

// Ids for content's polygons, in order: taken from `previous` where equal, else next_id++, which
// must stay below `end` (the end of its id space: LimitExceeded kPolygonIds).
std::vector<PolygonId> match_ids(const IdSource& previous, const LabeledSet& content,
                                 PolygonId& next_id,
                                 PolygonId end = std::numeric_limits<PolygonId>::max());

}  // namespace edgeland::detail
