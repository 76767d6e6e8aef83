#include "wkt_tokens.hpp"

#include <cstdint>
#include <cstdio>
#include <limits>

#include "edgeland/io/wkt_reader.hpp"

namespace edgeland::wkt_detail {
namespace {

using Kind = Token::Kind;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool is_punct(char c) { return c == '(' || c == ')' || c == ','; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

char to_upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

[[noreturn]] void fail(WktErrorKind kind, TextPosition at, const std::string& reason) {
  fail_at(kind, at, reason);
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

// [+-]?[0-9]+ whose magnitude fits int64, as its value; anything else that starts like a number
// is reported with a precise reason (a decimal, an exponent, junk).
std::int64_t number_value(const Token& token) {
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
    // Two's complement: the negation of 2^63 is INT64_MIN, every other magnitude fits.
    return negative ? static_cast<std::int64_t>(~magnitude + 1)
                    : static_cast<std::int64_t>(magnitude);
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

Tokens split(std::string_view text) {
  Tokens out;
  std::vector<Token>& tokens = out.tokens;
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
      token.value = number_value(token);
    } else if (!is_letter(c)) {
      fail(WktErrorKind::kSyntax, at, "unexpected " + quoted(token.text));
    }
    tokens.push_back(token);
    at.column += end - i;
    i = end;
  }
  out.end = at;
  return out;
}

}  // namespace

bool equals_upper(std::string_view word, std::string_view upper) {
  if (word.size() != upper.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i) {
    if (to_upper(word[i]) != upper[i]) return false;
  }
  return true;
}

std::string quoted(std::string_view token) {
  // Appended piece by piece: g++ 12 warns (-Wrestrict, a false positive) on "'" + string.
  constexpr std::size_t kMaxShown = 32;
  const bool cut = token.size() > kMaxShown;
  std::string out;
  out.reserve(kMaxShown + 5);
  out.append(1, '\'').append(token.substr(0, kMaxShown)).append(cut ? "...'" : "'");
  return out;
}

void fail_at(WktErrorKind kind, TextPosition at, const std::string& reason) {
  WktError error(kind, describe_position(at) + ": " + reason);
  error.reason = reason;
  error.line = at.line;
  error.column = at.column;
  throw error;
}

std::string describe_position(TextPosition at) {
  return "line " + std::to_string(at.line) + ", column " + std::to_string(at.column);
}

namespace {

// A UTF-8 byte-order mark (which some editors write) is not part of the text.
std::string_view without_bom(std::string_view text) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (text.substr(0, kBom.size()) == kBom) text.remove_prefix(kBom.size());
  return text;
}

}  // namespace

Tokens tokenize(std::string_view input) {
  const std::string_view text = without_bom(input);
  check_bytes(text);
  return split(text);
}

}  // namespace edgeland::wkt_detail
