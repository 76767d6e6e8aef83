#pragma once
// Private to the WKT reader: the text split into tokens, each checked on its own (bytes, number
// literals), with its line and column. The structure is the parser's (wkt_reader.cpp).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "edgeland/io/wkt_reader.hpp"

namespace edgeland::wkt_detail {

struct TextPosition {
  std::size_t line = 1;  // 1-based
  std::size_t column = 1;
};

struct Token {
  enum class Kind : unsigned char { kOpen, kClose, kComma, kNumber, kWord };
  Kind kind;
  std::string_view text;
  TextPosition at;
  std::int64_t value = 0;  // kNumber: the integer (any int64; the bound is checked per vertex)
};

// The tokens of the text (a UTF-8 byte-order mark before it skipped) and the position just past
// its end. Throws WktError for a byte that is not printable ASCII or white space (kNotText),
// a decimal or exponent literal (kNotInteger), a malformed number or a stray character (kSyntax)
// and an integer beyond int64 (kCoordinateOutOfRange). O(n) in the text length.
struct Tokens {
  std::vector<Token> tokens;
  TextPosition end;
};
Tokens tokenize(std::string_view text);

// "line 3, column 14"
std::string describe_position(TextPosition at);

// A token quoted for a message, cut short so a megabyte of junk stays a one-line message.
std::string quoted(std::string_view token);

// Throws WktError(kind) with the message "line L, column C: reason", reason and position in
// their fields.
[[noreturn]] void fail_at(WktErrorKind kind, TextPosition at, const std::string& reason);

// Case-insensitive comparison with an upper-case keyword.
bool equals_upper(std::string_view word, std::string_view upper);

}  // namespace edgeland::wkt_detail
