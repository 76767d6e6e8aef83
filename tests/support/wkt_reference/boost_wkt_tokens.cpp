#include "boost_wkt_tokens.hpp"

#include <cstdint>
#include <cstdio>
#include <limits>

#include "edgeland/io/wkt_reader.hpp"

namespace edgeland::wkt_reference {
namespace {

using Kind = Token::Kind;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool is_punct(char c) { return c == '(' || c == ')' || c == ','; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

char to_upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

bool equals_upper(std::string_view word, std::string_view upper) {
  if (word.size() != upper.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i) {
    if (to_upper(word[i]) != upper[i]) return false;
  }
  return true;
}

// Quotes a token for a message, cut short so a megabyte of junk stays a one-line message.
std::string quoted(std::string_view token) {
  // Appended piece by piece: g++ 12 warns (-Wrestrict, a false positive) on "'" + string.
  constexpr std::size_t kMaxShown = 32;
  const bool cut = token.size() > kMaxShown;
  std::string out;
  out.reserve(kMaxShown + 5);
  out.append(1, '\'').append(token.substr(0, kMaxShown)).append(cut ? "...'" : "'");
  return out;
}

[[noreturn]] void fail(WktErrorKind kind, TextPosition at, const std::string& what) {
  WktError error(kind, describe_position(at) + ": " + what);
  error.line = at.line;
  error.column = at.column;
  throw error;
}

// Rejects any byte a WKT text cannot contain, before anything looks at the structure.
void check_bytes(std::string_view text) {
  TextPosition at;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (!is_space(text[i]) && (byte < 0x20 || byte > 0x7e)) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", byte);
      fail(WktErrorKind::kNotText, at,
           "not WKT text: byte " + std::string(hex) + " at offset " + std::to_string(i));
    }
    if (text[i] == '\n') {
      ++at.line;
      at.column = 1;
    } else {
      ++at.column;
    }
  }
}

// [+-]?[0-9]+ whose magnitude fits int64 (read_wkt's own range); anything else that starts
// like a number is reported here with a precise reason rather than as a "bad lexical cast".
void check_number(const Token& token) {
  std::string_view digits = token.text;
  const bool negative = digits.front() == '-';
  if (digits.front() == '+' || digits.front() == '-') digits.remove_prefix(1);
  bool all_digits = !digits.empty();
  for (char c : digits) all_digits = all_digits && is_digit(c);
  if (all_digits) {
    // |INT64_MIN| = 2^63 is allowed for negative values.
    const std::uint64_t limit =
        static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()) + (negative ? 1 : 0);
    std::uint64_t magnitude = 0;
    for (char c : digits) {
      const auto digit = static_cast<std::uint64_t>(c - '0');
      if (magnitude > (limit - digit) / 10) {
        fail(WktErrorKind::kCoordinateOutOfRange, token.at,
             "coordinate " + quoted(token.text) +
                 " is beyond the bound |c| <= " + std::to_string(kCoordBound));
      }
      magnitude = magnitude * 10 + digit;
    }
    return;
  }
  // A decimal or exponent literal: digits with at most one '.', then an optional exponent.
  bool seen_digit = false;
  bool seen_dot = false;
  bool seen_exponent = false;
  bool decimal = true;
  for (std::size_t i = 0; i < digits.size() && decimal; ++i) {
    const char c = digits[i];
    if (is_digit(c)) {
      seen_digit = true;
    } else if (c == '.' && !seen_dot && !seen_exponent) {
      seen_dot = true;
    } else if ((c == 'e' || c == 'E') && seen_digit && !seen_exponent) {
      seen_exponent = true;
      if (i + 1 < digits.size() && (digits[i + 1] == '+' || digits[i + 1] == '-')) ++i;
      decimal = i + 1 < digits.size();
    } else {
      decimal = false;
    }
  }
  if (decimal && seen_digit && (seen_dot || seen_exponent)) {
    fail(WktErrorKind::kNotInteger, token.at,
         "coordinate " + quoted(token.text) + " is not an integer; only integers are accepted");
  }
  fail(WktErrorKind::kSyntax, token.at, "malformed number " + quoted(token.text));
}

std::vector<Token> split(std::string_view text) {
  std::vector<Token> tokens;
  TextPosition at;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (is_space(c)) {
      if (c == '\n') {
        ++at.line;
        at.column = 1;
      } else {
        ++at.column;
      }
      ++i;
      continue;
    }
    std::size_t end = i + 1;
    if (!is_punct(c)) {
      while (end < text.size() && !is_space(text[end]) && !is_punct(text[end])) ++end;
    }
    Token token{Kind::kWord, text.substr(i, end - i), at};
    if (c == '(') {
      token.kind = Kind::kOpen;
    } else if (c == ')') {
      token.kind = Kind::kClose;
    } else if (c == ',') {
      token.kind = Kind::kComma;
    } else if (is_digit(c) || c == '+' || c == '-' || c == '.') {
      token.kind = Kind::kNumber;
      check_number(token);
    } else if (!is_letter(c)) {
      fail(WktErrorKind::kSyntax, at, "unexpected " + quoted(token.text));
    }
    tokens.push_back(token);
    at.column += end - i;
    i = end;
  }
  return tokens;
}

// The geometry type comes first; the only other word allowed is EMPTY right after it.
bool check_words(const std::vector<Token>& tokens) {
  const Token& first = tokens.front();
  if (first.kind != Kind::kWord) {
    fail(WktErrorKind::kSyntax, first.at,
         "expected POLYGON or MULTIPOLYGON, found " + quoted(first.text));
  }
  const bool multi = equals_upper(first.text, "MULTIPOLYGON");
  if (!multi && !equals_upper(first.text, "POLYGON")) {
    fail(WktErrorKind::kUnsupportedGeometry, first.at,
         "unsupported geometry " + quoted(first.text) + "; expected POLYGON or MULTIPOLYGON");
  }
  for (std::size_t i = 1; i < tokens.size(); ++i) {
    const Token& token = tokens[i];
    if (token.kind != Kind::kWord) continue;
    if (i == 1 && equals_upper(token.text, "EMPTY")) continue;
    if (i == 1 && (equals_upper(token.text, "Z") || equals_upper(token.text, "M") ||
                   equals_upper(token.text, "ZM"))) {
      fail(WktErrorKind::kWrongDimension, token.at,
           quoted(token.text) + " coordinates are not supported; points are 2D (x y)");
    }
    fail(WktErrorKind::kSyntax, token.at, "unexpected word " + quoted(token.text));
  }
  return multi;
}

// Every run of numbers is one point and must hold exactly x and y: read_wkt would read
// "10 0 5" as (10 0), (5 0) and a lone "1" as (1 0).
std::vector<TextPosition> check_points(const std::vector<Token>& tokens) {
  std::vector<TextPosition> points;
  std::size_t i = 0;
  while (i < tokens.size()) {
    if (tokens[i].kind != Kind::kNumber) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < tokens.size() && tokens[end].kind == Kind::kNumber) ++end;
    if (end - i != 2) {
      fail(WktErrorKind::kWrongDimension, tokens[i].at,
           "point has " + std::to_string(end - i) + " coordinate(s); expected 2 (x y)");
    }
    points.push_back(tokens[i].at);
    i = end;
  }
  return points;
}

// Neighbouring tokens that read_wkt lets through silently: a comma must separate two points
// or two parenthesised lists (",," "(," ",)" read as (0 0) points or dropped), lists need a
// comma between them (")(" ), and "()" is an empty geometry.
void check_pairs(const std::vector<Token>& tokens) {
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& token = tokens[i];
    const Kind prev = i > 0 ? tokens[i - 1].kind : Kind::kWord;
    const bool has_next = i + 1 < tokens.size();
    const Kind next = has_next ? tokens[i + 1].kind : Kind::kWord;
    if (token.kind == Kind::kComma) {
      const bool between_points = prev == Kind::kNumber && has_next && next == Kind::kNumber;
      const bool between_lists = prev == Kind::kClose && has_next && next == Kind::kOpen;
      if (!between_points && !between_lists) {
        fail(WktErrorKind::kSyntax, token.at,
             "misplaced ','; a comma separates two points or two parenthesised lists");
      }
    } else if (token.kind == Kind::kOpen && has_next && next == Kind::kClose) {
      fail(WktErrorKind::kEmptyGeometry, token.at, "empty list '()'");
    } else if (token.kind == Kind::kClose && has_next && next == Kind::kOpen) {
      fail(WktErrorKind::kSyntax, tokens[i + 1].at, "missing ',' between ')' and '('");
    }
  }
}

}  // namespace

std::string describe_position(TextPosition at) {
  return "line " + std::to_string(at.line) + ", column " + std::to_string(at.column);
}

namespace {

// OGC: an EMPTY member of a MULTIPOLYGON is the empty set, so it is dropped with one comma
// beside it (read_wkt takes none); with no member left the text is MULTIPOLYGON EMPTY.
std::vector<Token> drop_empty_members(const std::vector<Token>& tokens) {
  std::vector<Token> kept;
  kept.reserve(tokens.size());
  int depth = 0;
  bool dropped = false;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& token = tokens[i];
    depth += token.kind == Kind::kOpen ? 1 : token.kind == Kind::kClose ? -1 : 0;
    const bool member = depth == 1 && i > 0 && i + 1 < tokens.size() &&
                        (tokens[i - 1].kind == Kind::kOpen || tokens[i - 1].kind == Kind::kComma) &&
                        (tokens[i + 1].kind == Kind::kClose || tokens[i + 1].kind == Kind::kComma);
    if (!member || token.kind != Kind::kWord || !equals_upper(token.text, "EMPTY")) {
      kept.push_back(token);
      continue;
    }
    dropped = true;
    // The comma before it goes with it, else the one after, unless a ')' follows that comma:
    // "(EMPTY, )" has a stray comma, as io/'s reader says (RapidCheck found the disagreement).
    if (kept.back().kind == Kind::kComma) {
      kept.pop_back();
    } else if (tokens[i + 1].kind == Kind::kComma &&
               !(i + 2 < tokens.size() && tokens[i + 2].kind == Kind::kClose)) {
      ++i;
    }
  }
  if (dropped && kept.size() == 3 && kept[1].kind == Kind::kOpen && kept[2].kind == Kind::kClose) {
    kept.pop_back();
    kept.back() = Token{Kind::kWord, "EMPTY", kept.back().at};
  }
  return kept;
}

// A UTF-8 byte-order mark (which some editors write) is not part of the text.
std::string_view without_bom(std::string_view text) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (text.substr(0, kBom.size()) == kBom) text.remove_prefix(kBom.size());
  return text;
}

}  // namespace

CheckedText check_tokens(std::string_view input) {
  const std::string_view text = without_bom(input);
  check_bytes(text);
  std::vector<Token> tokens = split(text);
  if (!tokens.empty() && equals_upper(tokens.front().text, "MULTIPOLYGON")) {
    tokens = drop_empty_members(tokens);
  }
  if (tokens.empty()) {
    throw WktError(WktErrorKind::kEmptyInput,
                   "empty input; expected a WKT POLYGON or MULTIPOLYGON");
  }
  CheckedText checked;
  checked.multi = check_words(tokens);
  // check_words allows one word after the type: EMPTY.
  checked.empty_polygon = !checked.multi && tokens.size() == 2 && tokens[1].kind == Kind::kWord;
  checked.points = check_points(tokens);
  check_pairs(tokens);
  for (const Token& token : tokens) {
    if (!checked.canonical.empty()) checked.canonical += ' ';
    checked.canonical += token.text;
  }
  return checked;
}

}  // namespace edgeland::wkt_reference
