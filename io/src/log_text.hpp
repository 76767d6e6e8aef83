#pragma once
// What the two log readers (clip_log.hpp, landscape_log.hpp) share beyond the lines and words
// of log_words.hpp: error places, hashes in hex, and where a refused shape went wrong.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "edgeland/io/log_words.hpp"
#include "edgeland/io/wkt_reader.hpp"

namespace edgeland::log {

// "line N" or "line N, column C" (column 0: not known), as the logs' errors begin.
std::string line_place(std::size_t line, std::size_t column);

// A 64-bit hash as 16 lower-case hex digits (the state hashes both replays print).
std::string hex16(std::uint64_t value);

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
