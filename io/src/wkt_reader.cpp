// The WKT reader (wkt_reader.hpp): tokens (wkt_tokens.cpp), then the grammar of OGC Simple
// Features' <polygon text> and <multipolygon text> (OGC 06-103r4, 7.2) with integer points,
// one loop per level of parentheses: geometry -> polygon -> ring -> point. The depth is fixed,
// so nothing recurses on the input, and the first token that does not fit is the error.
#include "edgeland/io/wkt_reader.hpp"

#include <utility>

#include "wkt_tokens.hpp"

namespace edgeland {
namespace {

using wkt_detail::describe_position;
using wkt_detail::equals_upper;
using wkt_detail::fail_at;
using wkt_detail::quoted;
using wkt_detail::TextPosition;
using wkt_detail::Token;
using Kind = Token::Kind;

// A ring as read: its points (the closing one included) and where each starts.
struct RingText {
  std::vector<Point64> points;
  std::vector<TextPosition> at;
};

class Parser {
 public:
  explicit Parser(wkt_detail::Tokens tokens) : t_(std::move(tokens)) {}

  WktGeometry geometry() {
    if (t_.tokens.empty()) fail_empty();
    WktGeometry out;
    out.type = geometry_type();
    if (next_is(Kind::kWord)) {
      empty_or_dimension();
      out.type = WktGeometry::Type::kMultiPolygon;  // POLYGON EMPTY: the empty set
    } else if (out.type == WktGeometry::Type::kMultiPolygon) {
      out.polygons = multipolygon_text();
    } else {
      out.polygons.push_back(polygon_text(0));
    }
    if (const Token* extra = peek()) {
      fail_at(WktErrorKind::kSyntax, extra->at,
              "malformed WKT: unexpected " + quoted(extra->text) + " after the geometry");
    }
    return out;
  }

 private:
  [[noreturn]] static void fail_empty() {
    const std::string reason = "empty input; expected a WKT POLYGON or MULTIPOLYGON";
    WktError error(WktErrorKind::kEmptyInput, reason);
    error.reason = reason;
    throw error;
  }

  const Token* peek() const { return i_ < t_.tokens.size() ? &t_.tokens[i_] : nullptr; }
  bool next_is(Kind kind) const { return peek() && peek()->kind == kind; }
  bool next_is_word(std::string_view upper) const {
    return next_is(Kind::kWord) && equals_upper(peek()->text, upper);
  }

  // The next token, which must be of `kind` (`expected` names it in the message).
  const Token& take(Kind kind, const char* expected) {
    if (!next_is(kind)) unexpected(expected);
    depth_ += kind == Kind::kOpen ? 1 : kind == Kind::kClose ? -1 : 0;
    return t_.tokens[i_++];
  }

  [[noreturn]] void unexpected(const std::string& expected) const {
    const Token* token = peek();
    if (!token) {
      // The text ends inside the geometry: most likely cut short, so say what closes it.
      const std::string what = depth_ > 0 ? "')'" : expected;
      fail_at(WktErrorKind::kSyntax, t_.end,
              "malformed WKT: expected " + what + " at the end of the text");
    }
    if (token->kind == Kind::kComma) {
      fail_at(WktErrorKind::kSyntax, token->at,
              "misplaced ','; a comma separates two points or two parenthesised lists");
    }
    if (token->kind == Kind::kOpen && i_ > 0 && t_.tokens[i_ - 1].kind == Kind::kClose) {
      fail_at(WktErrorKind::kSyntax, token->at, "missing ',' between ')' and '('");
    }
    fail_at(WktErrorKind::kSyntax, token->at,
            "malformed WKT: expected " + expected + ", found " + quoted(token->text));
  }

  WktGeometry::Type geometry_type() {
    const Token& first = t_.tokens.front();
    if (first.kind != Kind::kWord) {
      fail_at(WktErrorKind::kSyntax, first.at,
              "expected POLYGON or MULTIPOLYGON, found " + quoted(first.text));
    }
    ++i_;
    if (equals_upper(first.text, "MULTIPOLYGON")) return WktGeometry::Type::kMultiPolygon;
    if (equals_upper(first.text, "POLYGON")) return WktGeometry::Type::kPolygon;
    fail_at(WktErrorKind::kUnsupportedGeometry, first.at,
            "unsupported geometry " + quoted(first.text) + "; expected POLYGON or MULTIPOLYGON");
  }

  // The word after the type: EMPTY, or a dimension this reader does not take.
  void empty_or_dimension() {
    const Token& word = t_.tokens[i_];
    if (equals_upper(word.text, "EMPTY")) {
      ++i_;
      return;
    }
    if (equals_upper(word.text, "Z") || equals_upper(word.text, "M") ||
        equals_upper(word.text, "ZM")) {
      fail_at(WktErrorKind::kWrongDimension, word.at,
              quoted(word.text) + " coordinates are not supported; points are 2D (x y)");
    }
    fail_at(WktErrorKind::kSyntax, word.at, "unexpected word " + quoted(word.text));
  }

  // '(' then ')' is an empty list, which OGC writes as EMPTY.
  void refuse_empty_list(const Token& open) const {
    if (next_is(Kind::kClose)) fail_at(WktErrorKind::kEmptyGeometry, open.at, "empty list '()'");
  }

  // ( member {, member} ), a member being a polygon text or EMPTY (the empty set: dropped,
  // so the members after it are numbered as if it were absent).
  std::vector<WktPolygon> multipolygon_text() {
    refuse_empty_list(take(Kind::kOpen, "'('"));
    std::vector<WktPolygon> polygons;
    while (true) {
      if (next_is_word("EMPTY")) {
        ++i_;
      } else if (next_is(Kind::kOpen)) {
        polygons.push_back(polygon_text(polygons.size()));
      } else {
        unexpected("a polygon '(' or EMPTY");
      }
      if (!next_is(Kind::kComma)) break;
      ++i_;
    }
    take(Kind::kClose, "',' or ')'");
    return polygons;
  }

  // ( ring {, ring} ): the exterior, then the holes.
  WktPolygon polygon_text(std::size_t polygon) {
    refuse_empty_list(take(Kind::kOpen, "'('"));
    WktPolygon out;
    out.exterior = ring_text(polygon, 0);
    while (next_is(Kind::kComma)) {
      ++i_;
      out.holes.push_back(ring_text(polygon, out.holes.size() + 1));
    }
    take(Kind::kClose, "',' or ')'");
    return out;
  }

  // ( point {, point} ), checked as a ring and returned without its closing point.
  Ring ring_text(std::size_t polygon, std::size_t ring) {
    refuse_empty_list(take(Kind::kOpen, "a ring '('"));
    RingText text;
    while (true) {
      point(text);
      if (!next_is(Kind::kComma)) break;
      ++i_;
    }
    take(Kind::kClose, "',' or ')'");
    return checked_ring(text, polygon, ring);
  }

  // x y: exactly two integers, appended to the ring with where they start.
  void point(RingText& text) {
    const Token& x = take(Kind::kNumber, "a point (x y)");
    std::size_t count = 1;
    for (; next_is(Kind::kNumber); ++i_) ++count;
    if (count != 2) {
      fail_at(WktErrorKind::kWrongDimension, x.at,
              "point has " + std::to_string(count) + " coordinate(s); expected 2 (x y)");
    }
    text.points.push_back({x.value, t_.tokens[i_ - 1].value});
    text.at.push_back(x.at);
  }

  // The checks of a ring, vertex by vertex: in range, then at least two points, then closed.
  static Ring checked_ring(const RingText& text, std::size_t polygon, std::size_t ring) {
    const std::vector<Point64>& p = text.points;
    for (std::size_t v = 0; v < p.size(); ++v) {
      if (!in_range(p[v])) {
        fail_vertex(WktErrorKind::kCoordinateOutOfRange, text, polygon, ring, v,
                    "coordinate (" + std::to_string(p[v].x) + " " + std::to_string(p[v].y) +
                        ") is beyond the bound |c| <= " + std::to_string(kCoordBound));
      }
    }
    const std::size_t last = p.size() - 1;
    if (p.size() < 2) {  // two points close a ring (of one vertex, for validate to refuse)
      fail_vertex(WktErrorKind::kTooFewPoints, text, polygon, ring, last,
                  "ring has " + std::to_string(p.size()) +
                      " point(s); a ring needs at least 3 points, the last repeating the first");
    }
    if (p.front() != p.back()) {
      fail_vertex(WktErrorKind::kUnclosedRing, text, polygon, ring, last,
                  "ring is not closed; its last point must repeat its first point (" +
                      std::to_string(p.front().x) + " " + std::to_string(p.front().y) + ")");
    }
    return Ring(p.begin(), p.end() - 1);  // the kernel's rings do not repeat the first vertex
  }

  [[noreturn]] static void fail_vertex(WktErrorKind kind, const RingText& text, std::size_t polygon,
                                       std::size_t ring, std::size_t vertex,
                                       const std::string& what) {
    const std::string names = "polygon " + std::to_string(polygon) + " ring " +
                              std::to_string(ring) + " vertex " + std::to_string(vertex);
    const TextPosition at = text.at[vertex];
    WktError error(kind, names + " (" + describe_position(at) + "): " + what);
    error.reason = names + ": " + what;
    error.polygon = polygon;
    error.ring = ring;
    error.vertex = vertex;
    error.where = text.points[vertex];
    error.line = at.line;
    error.column = at.column;
    throw error;
  }

  wkt_detail::Tokens t_;
  std::size_t i_ = 0;  // the next token
  int depth_ = 0;      // parentheses open
};

}  // namespace

const char* wkt_error_kind_name(WktErrorKind kind) noexcept {
  switch (kind) {
    case WktErrorKind::kEmptyInput:
      return "empty-input";
    case WktErrorKind::kNotText:
      return "not-text";
    case WktErrorKind::kSyntax:
      return "syntax";
    case WktErrorKind::kNotInteger:
      return "not-integer";
    case WktErrorKind::kWrongDimension:
      return "wrong-dimension";
    case WktErrorKind::kUnsupportedGeometry:
      return "unsupported-geometry";
    case WktErrorKind::kEmptyGeometry:
      return "empty-geometry";
    case WktErrorKind::kTooFewPoints:
      return "too-few-points";
    case WktErrorKind::kUnclosedRing:
      return "unclosed-ring";
    case WktErrorKind::kCoordinateOutOfRange:
      return "coordinate-out-of-range";
  }
  return "unknown";  // not reached: every kind is named above
}

WktError::WktError(WktErrorKind error_kind, const std::string& message)
    : Error(message), kind(error_kind), reason(message) {}

WktGeometry read_wkt(std::string_view text) {
  return Parser(wkt_detail::tokenize(text)).geometry();
}

}  // namespace edgeland
