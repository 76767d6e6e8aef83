#pragma once
// WKT POLYGON / MULTIPOLYGON text with decimal coordinates, as peers write it, read into exact
// decimals. edgeland's own reader (io/.../wkt_reader.hpp) accepts integers only, by design; the
// peers' data is decimal, so it is read here and scaled to integers (integer_operands.hpp).
// Rings are kept as written, closing point included; whether a ring is closed is decided after
// scaling (some peers' rings close only up to the last digit, e.g. Boost.Geometry's
// ggl_list_20110820_christophe).
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "exact_decimal.hpp"

namespace edgeland::test {

struct DecimalPoint {
  Decimal x, y;
};
using DecimalRing = std::vector<DecimalPoint>;
// One OGC polygon: element 0 is the exterior, the rest are holes.
using DecimalPolygon = std::vector<DecimalRing>;
using DecimalGeometry = std::vector<DecimalPolygon>;

// Throws std::invalid_argument naming the offset on malformed text (a broken data file).
DecimalGeometry read_decimal_wkt(std::string_view text);

}  // namespace edgeland::test
