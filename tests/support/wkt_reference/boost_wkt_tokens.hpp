#pragma once
// Private to the WKT reader: the lexical checks made before the text is handed to
// Boost.Geometry's read_wkt, for the inputs read_wkt accepts silently (TOOLCHAIN.md pitfall 6).
// This is not a parser: nesting and the order of the parts are read_wkt's job. It splits the
// text into tokens and checks each token, and each pair of neighbouring tokens, on its own.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace edgeland::wkt_reference {

struct TextPosition {
  std::size_t line = 1;  // 1-based
  std::size_t column = 1;
};

struct Token {
  enum class Kind : unsigned char { kOpen, kClose, kComma, kNumber, kWord };
  Kind kind;
  std::string_view text;
  TextPosition at;
};

struct CheckedText {
  // The tokens joined by single spaces: what read_wkt is given. (Its tokenizer only drops
  // ' ', so a line break or tab inside the text would otherwise glue onto a number.)
  std::string canonical;
  // Whether the first token is MULTIPOLYGON (else POLYGON).
  bool multi = false;
  // The text is POLYGON EMPTY: the empty set.
  bool empty_polygon = false;
  // Where each point starts, in the order read_wkt returns the points (polygons, then rings,
  // then vertices), so errors found after reading can name the line and column too.
  std::vector<TextPosition> points;
};

// Throws WktError on the first token or token pair that is wrong. O(n) in the text length.
CheckedText check_tokens(std::string_view text);

// "line 3, column 14"
std::string describe_position(TextPosition at);

}  // namespace edgeland::wkt_reference
