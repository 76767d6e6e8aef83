#pragma once
// Reading WKT POLYGON / MULTIPOLYGON text with integer coordinates into the kernel's rings.
//
// Part of edgeland::io (io/README.md): plain C++20, no dependency beyond the kernel, so that it
// builds wherever the library does (Emscripten included). Every input is either returned
// exactly as written or rejected with a WktError; in particular (the inputs a lenient reader
// such as Boost.Geometry's read_wkt accepts silently, TOOLCHAIN.md pitfall 6):
//   * the text is printable ASCII (tabs and line breaks allowed), and not empty;
//   * every coordinate is an integer literal ("1.5", "1e3", "0x10" are rejected), and every
//     point has exactly two of them (no stray 3rd coordinate, no missing y, no Z/M);
//   * no empty points, stray commas or missing commas (",,", "(,", ",)", ")(") and no "()";
//   * every ring has at least 3 points and is closed (its last point repeats its first), and
//     every coordinate satisfies |c| <= kCoordBound (the error names the polygon, ring and
//     vertex).
// As in OGC, "MULTIPOLYGON EMPTY", "POLYGON EMPTY" and EMPTY members of a MULTIPOLYGON are the
// empty set (POLYGON EMPTY reads as a MULTIPOLYGON without members: there is no polygon). A
// UTF-8 byte-order mark before the text is skipped. Keywords are case-insensitive.
// Nothing else about the shape is checked here: simplicity, orientation and vertex count are
// the kernel's validate() (kernel/validate.hpp).
//
// Complexity: O(n) time and memory in the length of the text; never recurses (the grammar has
// a fixed depth, so nesting deeper than a MULTIPOLYGON's is an error at its fourth '(').
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/kernel/validate.hpp"

namespace edgeland {

// Why a text was rejected.
enum class WktErrorKind : std::uint8_t {
  kEmptyInput,            // no text at all, or only white space
  kNotText,               // a byte that is not printable ASCII, tab or line break
  kSyntax,                // not well-formed WKT: a token where another belongs, a stray ','
  kNotInteger,            // a decimal or exponent coordinate such as 1.5 or 1e3
  kWrongDimension,        // a point without exactly two coordinates, or a Z/M qualifier
  kUnsupportedGeometry,   // a geometry other than POLYGON / MULTIPOLYGON
  kEmptyGeometry,         // an empty list "()" (POLYGON EMPTY is the empty set, not an error)
  kTooFewPoints,          // a ring of fewer than 3 points ("POLYGON ((0 0))")
  kUnclosedRing,          // a ring whose last point is not its first
  kCoordinateOutOfRange,  // |c| > kCoordBound
};

// Stable lower-case name of a kind, e.g. "not-integer".
EDGELAND_EXPORT const char* wkt_error_kind_name(WktErrorKind kind) noexcept;

// The one error type of the reader. what() is a single line: the position, then `reason`
// ("line 1, column 16: coordinate '10.5' is not an integer; ..."; an error about a vertex reads
// "polygon 0 ring 0 vertex 1 (line 1, column 16): coordinate ..."). Fields that do not apply
// hold 0 (line, column) or kNone (polygon, ring, vertex). A reader of text that embeds WKT
// (the logs) names the place in its own terms from line/column and `reason`.
class EDGELAND_EXPORT WktError : public Error {
 public:
  WktError(WktErrorKind kind, const std::string& message);
  WktErrorKind kind;
  std::string reason;    // what() without the position (the vertex's names stay in it)
  std::size_t line = 0;  // 1-based position in the text, when known
  std::size_t column = 0;
  std::size_t polygon = kNone;  // index of the polygon in the MULTIPOLYGON (0 for a POLYGON)
  std::size_t ring = kNone;     // 0 = exterior ring, 1.. = holes
  std::size_t vertex = kNone;   // index of the point in its ring
  Point64 where;                // the offending point (kCoordinateOutOfRange, kUnclosedRing)
};

// One WKT polygon: its exterior ring and its holes, each without the closing vertex and in
// the order written (orientation is not changed).
struct WktPolygon {
  Ring exterior;
  std::vector<Ring> holes;
};

struct WktGeometry {
  enum class Type : std::uint8_t { kPolygon, kMultiPolygon };
  Type type = Type::kPolygon;
  std::vector<WktPolygon> polygons;  // exactly one for kPolygon; any number for kMultiPolygon
};

// Parses `text` (one geometry; surrounding white space is ignored). Throws WktError.
EDGELAND_EXPORT WktGeometry read_wkt(std::string_view text);

}  // namespace edgeland
