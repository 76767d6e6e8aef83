#pragma once
// The Boost.Geometry-based WKT reader edgeland used before io/ had its own parser: an oracle for
// io/'s read_wkt. Same contract (edgeland/io/wkt_reader.hpp): returns the geometry or throws
// WktError.
#include <string_view>

#include "edgeland/io/wkt_reader.hpp"

namespace edgeland::wkt_reference {

WktGeometry read_wkt_with_boost(std::string_view text);

}  // namespace edgeland::wkt_reference
