#include "edgeland/io/log_kind.hpp"

#include "edgeland/io/clip_log.hpp"
#include "edgeland/spatial/log_format.hpp"
#include "log_text.hpp"

namespace edgeland::log {
namespace {

constexpr const char* kWhatLogsStartWith =
    "a landscape log starts with `world X0 Y0 X1 Y1 [MATERIAL]`, a continuous-clip log with a "
    "step: set, union, intersection, difference or xor";

bool is_clip_step(std::string_view word) {
  for (const StepKind k : {StepKind::kSet, StepKind::kUnion, StepKind::kIntersection,
                           StepKind::kDifference, StepKind::kXor})
    if (word == step_keyword(k)) return true;
  return false;
}

}  // namespace

LogStart log_start(std::string_view text) {
  for (std::size_t line = 1; !text.empty(); ++line) {
    std::string_view rest = trim_blanks(take_line(text));
    if (is_skipped_line(rest)) continue;
    const std::string_view word = take_word(rest);
    const LogKind kind = word == kWorldKeyword ? LogKind::kLandscape
                         : is_clip_step(word)  ? LogKind::kClip
                                               : LogKind::kUnknown;
    return {kind, line, printable_excerpt(word)};
  }
  return {};
}

std::optional<std::string> log_start_problem(const LogStart& start) {
  if (start.kind == LogKind::kNoCommand)
    return std::string("no command: the file is empty or holds only comments and blank lines (") +
           kWhatLogsStartWith + ")";
  if (start.kind == LogKind::kUnknown)
    return "line " + std::to_string(start.line) + ": unknown command '" + start.word + "' (" +
           kWhatLogsStartWith + ")";
  return std::nullopt;
}

}  // namespace edgeland::log
