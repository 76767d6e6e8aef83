#include "log_text.hpp"

namespace edgeland::log {

std::string_view trim_blanks(std::string_view s) noexcept {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

std::string_view take_line(std::string_view& text) noexcept {
  const std::size_t newline = text.find('\n');
  const std::string_view line = text.substr(0, newline);
  text.remove_prefix(newline == std::string_view::npos ? text.size() : newline + 1);
  return line;
}

std::string_view take_word(std::string_view& rest) noexcept {
  std::size_t end = 0;
  while (end < rest.size() && !is_blank(rest[end])) ++end;
  const std::string_view word = rest.substr(0, end);
  rest = trim_blanks(rest.substr(end));
  return word;
}

std::string printable_excerpt(std::string_view word) {
  constexpr std::size_t kMax = 24;
  std::string out;
  for (std::size_t i = 0; i < word.size() && i < kMax; ++i) {
    const unsigned char c = static_cast<unsigned char>(word[i]);
    out += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
  }
  if (word.size() > kMax) out += "...";
  return out;
}

std::string line_place(std::size_t line, std::size_t column) {
  std::string out = "line " + std::to_string(line);
  if (column != 0) out += ", column " + std::to_string(column);
  return out;
}

std::string hex16(std::uint64_t value) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out(16, '0');
  for (int i = 15; i >= 0; --i) {
    out[static_cast<std::size_t>(i)] = kHex[value & 0xf];
    value >>= 4;
  }
  return out;
}

ShapeError shape_error(std::string_view line, std::string_view wkt, const WktError& error) {
  std::int64_t open = 0;
  for (const char c : wkt) open += c == '(' ? 1 : c == ')' ? -1 : 0;
  ShapeError out{error.reason, 0};
  if (open > 0) {
    out.reason += " (the line ends with " + std::to_string(open) +
                  " parenthesis(es) open: a step's shape must fit on its one line)";
  }
  // A log line holds no line break, so the reader's position is on its line 1.
  if (error.line == 1 && error.column != 0) {
    out.column = static_cast<std::size_t>(wkt.data() - line.data()) + error.column;
  }
  return out;
}

}  // namespace edgeland::log
