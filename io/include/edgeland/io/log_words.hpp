#pragma once
// The lines and words of edgeland's text formats: the landscape and continuous-clip logs read
// with them, and so can a program's own line-based scripts (the desktop demo's input scripts),
// so that every text format of the project splits lines and words, skips blank and comment
// lines and quotes bad words the same way. One command per line, words separated by spaces or
// tabs, a final '\r' ignored, '#' starting a comment line.
//
// Part of edgeland::io (io/README.md).
#include <string>
#include <string_view>

#include "edgeland/kernel/export.hpp"

namespace edgeland::log {

// A space, a tab or a carriage return (so CRLF line ends read like LF).
constexpr bool is_blank(char c) noexcept { return c == ' ' || c == '\t' || c == '\r'; }

// `s` without its leading and trailing blanks.
EDGELAND_EXPORT std::string_view trim_blanks(std::string_view s) noexcept;

// True for a line (already trimmed) that holds no command: empty, or a '#' comment.
constexpr bool is_skipped_line(std::string_view trimmed) noexcept {
  return trimmed.empty() || trimmed.front() == '#';
}

// Removes the first line of `text` (up to and without its '\n') and returns it.
EDGELAND_EXPORT std::string_view take_line(std::string_view& text) noexcept;

// Removes the first word of `rest` (up to the first blank) and returns it; `rest` keeps what
// follows, without its leading blanks.
EDGELAND_EXPORT std::string_view take_word(std::string_view& rest) noexcept;

// A printable excerpt of a word for an error message (the line may be binary junk): at most
// 24 characters, other bytes shown as '?', "..." after a longer word.
EDGELAND_EXPORT std::string printable_excerpt(std::string_view word);

}  // namespace edgeland::log
