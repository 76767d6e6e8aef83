// The reader edgeland had before io/ (issue 27, point 13): lexical checks, then Boost.Geometry's
// read_wkt for the structure, then the ring checks read_wkt does not make. Kept in the tests
// as an independent oracle for io/'s own parser (tests/io/wkt_reader_oracle_test.cpp).
#include "boost_wkt_reader.hpp"

#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/geometry/io/wkt/read.hpp>
#include <exception>
#include <new>

#include "boost_wkt_tokens.hpp"

namespace edgeland {
namespace {

namespace bg = boost::geometry;
using BgPoint = bg::model::d2::point_xy<std::int64_t>;
// Counter-clockwise and closed: read_wkt neither reorders nor closes rings (verified), so the
// template arguments only document what we expect; the checks below enforce it.
using BgPolygon = bg::model::polygon<BgPoint, /*ClockWise=*/false, /*Closed=*/true>;
using BgMultiPolygon = bg::model::multi_polygon<BgPolygon>;
using BgRing = BgPolygon::ring_type;

using wkt_reference::TextPosition;

// Boost's messages end with " in '<the whole text>'" (or " in (...)"): keep the reason and the
// offending token, drop the echo so the message stays one short line.
std::string boost_reason(const std::exception& error) {
  std::string reason = error.what();
  for (const char* echo : {" in '", " in ("}) {
    const std::size_t cut = reason.find(echo);
    if (cut != std::string::npos) reason.resize(cut);
  }
  constexpr std::string_view kLexicalCast =
      "bad lexical cast: source type value could not be interpreted as target";
  if (reason.compare(0, kLexicalCast.size(), kLexicalCast) == 0) {
    reason = "expected a number" + reason.substr(kLexicalCast.size());
  }
  if (reason.find(" at '") == std::string::npos) reason += " at the end of the text";
  if (!reason.empty() && reason[0] >= 'A' && reason[0] <= 'Z')
    reason[0] = static_cast<char>(reason[0] - 'A' + 'a');
  constexpr std::size_t kMaxLength = 160;
  if (reason.size() > kMaxLength) reason = reason.substr(0, kMaxLength) + "...";
  return reason;
}

// Converts one ring, checking the bound and the closure read_wkt does not check.
class RingConverter {
 public:
  explicit RingConverter(const std::vector<TextPosition>& points) : points_(points) {}

  Ring convert(const BgRing& in, std::size_t polygon, std::size_t ring) {
    const std::size_t first_point = next_point_;
    next_point_ += in.size();
    if (in.empty()) {
      WktError error(WktErrorKind::kEmptyGeometry, "polygon " + std::to_string(polygon) + " ring " +
                                                       std::to_string(ring) + " is empty");
      error.polygon = polygon;
      error.ring = ring;
      throw error;
    }
    Ring out;
    out.reserve(in.size());
    for (std::size_t v = 0; v < in.size(); ++v) {
      const Point64 p{in[v].x(), in[v].y()};
      if (!in_range(p)) {
        fail(WktErrorKind::kCoordinateOutOfRange, polygon, ring, v, p, first_point + v,
             "coordinate (" + std::to_string(p.x) + " " + std::to_string(p.y) +
                 ") is beyond the bound |c| <= " + std::to_string(kCoordBound));
      }
      out.push_back(p);
    }
    const std::size_t last = in.size() - 1;
    if (in.size() < 2) {  // two points close a ring (of one vertex, for validate to refuse)
      fail(WktErrorKind::kTooFewPoints, polygon, ring, last, out.back(), first_point + last,
           "ring has " + std::to_string(in.size()) +
               " point(s); a ring needs at least 3 points, the last repeating the first");
    }
    if (out.front() != out.back()) {
      fail(WktErrorKind::kUnclosedRing, polygon, ring, last, out.back(), first_point + last,
           "ring is not closed; its last point must repeat its first point (" +
               std::to_string(out.front().x) + " " + std::to_string(out.front().y) + ")");
    }
    out.pop_back();  // the kernel's rings do not repeat the first vertex
    return out;
  }

 private:
  [[noreturn]] void fail(WktErrorKind kind, std::size_t polygon, std::size_t ring,
                         std::size_t vertex, Point64 where, std::size_t point_index,
                         const std::string& what) const {
    std::string prefix = "polygon " + std::to_string(polygon) + " ring " + std::to_string(ring) +
                         " vertex " + std::to_string(vertex);
    TextPosition at;
    const bool located = point_index < points_.size();
    if (located) at = points_[point_index];
    if (located) prefix += " (" + wkt_reference::describe_position(at) + ")";
    WktError error(kind, prefix + ": " + what);
    error.polygon = polygon;
    error.ring = ring;
    error.vertex = vertex;
    error.where = where;
    if (located) {
      error.line = at.line;
      error.column = at.column;
    }
    throw error;
  }

  const std::vector<TextPosition>& points_;
  std::size_t next_point_ = 0;  // global index of the next point, in reading order
};

WktPolygon convert_polygon(const BgPolygon& in, std::size_t index, RingConverter& rings) {
  WktPolygon out;
  out.exterior = rings.convert(in.outer(), index, 0);
  out.holes.reserve(in.inners().size());
  for (std::size_t h = 0; h < in.inners().size(); ++h) {
    out.holes.push_back(rings.convert(in.inners()[h], index, h + 1));
  }
  return out;
}

}  // namespace

namespace wkt_reference {

WktGeometry read_wkt_with_boost(std::string_view text) {
  const wkt_reference::CheckedText checked = wkt_reference::check_tokens(text);
  WktGeometry out;
  RingConverter rings(checked.points);
  try {
    if (checked.multi) {
      out.type = WktGeometry::Type::kMultiPolygon;
      BgMultiPolygon parsed;
      bg::read_wkt(checked.canonical, parsed);
      out.polygons.reserve(parsed.size());
      for (std::size_t i = 0; i < parsed.size(); ++i) {
        out.polygons.push_back(convert_polygon(parsed[i], i, rings));
      }
    } else {
      out.type = WktGeometry::Type::kPolygon;
      BgPolygon parsed;
      bg::read_wkt(checked.canonical, parsed);
      // read_wkt gives "POLYGON EMPTY" an empty exterior ring: the empty set (OGC), read as
      // a set without members, since there is no polygon to name.
      if (checked.empty_polygon) {
        out.type = WktGeometry::Type::kMultiPolygon;
        return out;
      }
      out.polygons.push_back(convert_polygon(parsed, 0, rings));
    }
  } catch (const WktError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& error) {
    // bg::read_wkt_exception and anything else read_wkt may throw (e.g. a bad_lexical_cast).
    throw WktError(WktErrorKind::kSyntax, "malformed WKT: " + boost_reason(error));
  }
  return out;
}

}  // namespace wkt_reference
}  // namespace edgeland
