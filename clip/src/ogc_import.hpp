#pragma once
// import_polygons(): foreign OGC polygons (rings in any orientation, often invalid) as the valid
// set of the region their rings wind around (clip/README.md, "Importing OGC polygons").
#include <vector>

#include "edgeland/clip/types.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

// Each polygon's first ring is its exterior, the rest its holes. Throws CoordinateOutOfRange
// naming (polygon, ring, vertex); InternalError as clip().
ClipResult import_ogc(const std::vector<std::vector<Ring>>& polygons, const ClipOptions& options);

}  // namespace edgeland::detail
