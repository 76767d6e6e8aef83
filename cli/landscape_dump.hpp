#pragma once
// The text form of a landscape's regions that `edgeland replay --dump` writes: one line per
// solid material that has polygons, in ascending order,
//   MATERIAL<TAB>MULTIPOLYGON (...)
// with every polygon of that material (the pieces cut at cell lines included) as the kernel's
// to_wkt writes them. Each line's MULTIPOLYGON is a valid set (`edgeland validate` accepts it),
// and `world ...` followed by `fill MATERIAL WKT` for each line is a landscape log of the same
// regions (what Landscape::start_log writes for an edited landscape), though in other cells
// under other ids.
#include <string>

#include "edgeland/spatial/landscape.hpp"

namespace edgeland::cli {

// The dump text, each line ending in '\n' (empty for an empty world). O(vertices).
std::string landscape_dump(const Landscape& landscape);

}  // namespace edgeland::cli
