#pragma once
// Writes integer polygons as WKT. (Reading WKT is the CLI's job, through Boost.Geometry.)
// Output: "MULTIPOLYGON (((x y, x y, ..., x y)), ...)" with each ring closed by repeating
// its first vertex, or "MULTIPOLYGON EMPTY".
#include <string>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland {

EDGELAND_EXPORT std::string to_wkt(const PolygonSet& set);
EDGELAND_EXPORT std::string to_wkt(const Polygon& polygon);  // "POLYGON ((...))"

}  // namespace edgeland
