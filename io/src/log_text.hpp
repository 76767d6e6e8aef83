#pragma once
// Line and word splitting shared by the two log readers (edit_log.hpp, landscape_log.hpp):
// both take one command per line, words separated by spaces or tabs, a final '\r' ignored.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "edgeland/io/wkt_reader.hpp"

namespace edgeland::log {

// A space, a tab or a carriage return (so CRLF line ends read like LF).
constexpr bool is_blank(char c) noexcept { return c == ' ' || c == '\t' || c == '\r'; }

// `s` without its leading and trailing blanks.
std::string_view trim_blanks(std::string_view s) noexcept;

// True for a line (already trimmed) that holds no command: empty, or a '#' comment.
constexpr bool is_skipped_line(std::string_view trimmed) noexcept {
  return trimmed.empty() || trimmed.front() == '#';
}

// Removes the first line of `text` (up to and without its '\n') and returns it.
std::string_view take_line(std::string_view& text) noexcept;

// Removes the first word of `rest` (up to the first blank) and returns it; `rest` keeps what
// follows, without its leading blanks.
std::string_view take_word(std::string_view& rest) noexcept;

// "line N" or "line N, column C" (column 0: not known), as the logs' errors begin.
std::string line_place(std::size_t line, std::size_t column);

// A 64-bit hash as 16 lower-case hex digits (the state hashes both replays print).
std::string hex16(std::uint64_t value);

// A printable excerpt of a word for an error message (the line may be binary junk): at most
// 24 characters, other bytes shown as '?'.
std::string printable_excerpt(std::string_view word);

// Where and why a step's shape was refused by the WKT reader, in the log line's terms: the
// reader's reason (when the line ends with parentheses still open, the shape most likely went
// on over the next line, and the message says that a shape must fit on its step's line), and
// the column of the error within the log line (0 when the reader named no place). `wkt` is a
// part of `line`.
struct ShapeError {
  std::string reason;
  std::size_t column = 0;
};
ShapeError shape_error(std::string_view line, std::string_view wkt, const WktError& error);

}  // namespace edgeland::log
