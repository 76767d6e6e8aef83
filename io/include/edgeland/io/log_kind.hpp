#pragma once
// Which kind of log a text is, told by its first command (blank and comment lines skipped), as
// `edgeland replay` tells them apart: `world` starts a landscape log (landscape_log.hpp), a
// clip step (set, union, intersection, difference, xor) a continuous-clip log (clip_log.hpp).
// A text with no command, or whose first command is neither, is no log of either kind, and
// log_start_problem says so in one line that names both kinds' first commands.
//
// Part of edgeland::io (io/README.md).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "edgeland/kernel/export.hpp"

namespace edgeland::log {

enum class LogKind : std::uint8_t {
  kLandscape,  // the first command is `world`
  kClip,       // the first command is a clip step
  kNoCommand,  // empty, or only blank and comment lines
  kUnknown,    // any other first word
};

struct LogStart {
  LogKind kind = LogKind::kNoCommand;
  std::size_t line = 0;  // the first command's line (1-based); 0 for kNoCommand
  std::string word;      // its first word, printable (other bytes as '?'), at most 24 characters
};

// O(length up to the first command).
EDGELAND_EXPORT LogStart log_start(std::string_view text);

// For kNoCommand and kUnknown, one line without a line break: "no command: ..." or "line N:
// unknown command 'W' (...)", naming what each kind of log starts with; nothing for a log.
EDGELAND_EXPORT std::optional<std::string> log_start_problem(const LogStart& start);

}  // namespace edgeland::log
