#pragma once
// The edit-log recorder (README.md "Landscape edit logs"): the log kept as a persistent list of
// lines (each written by log_format.hpp) so that copies of a recording landscape share it.
#include <memory>
#include <string>

#include "edgeland/spatial/landscape_state.hpp"

namespace edgeland::detail {

struct LogLine {
  LogLine() = default;
  LogLine(const LogLine&) = delete;
  LogLine& operator=(const LogLine&) = delete;
  // Unlinks the lines only this one holds one by one: a recursive release of a long log would
  // exhaust the stack.
  ~LogLine() {
    std::shared_ptr<const LogLine> p = std::move(prev);
    while (p && p.use_count() == 1) p = std::move(p->prev);
  }
  mutable std::shared_ptr<const LogLine> prev;
  std::string text;  // one line, with its '\n'
};

// A log that replays to the landscape's regions: the world line when nothing was edited since
// it was made, else the world line and one fill per material.
std::string state_log(const LandscapeState& s);
// The recorded log if the landscape records one, else state_log.
std::string replay_log(const LandscapeState& s);

// The state with `line` appended to its log.
void append_log(LandscapeState& state, const std::string& line);
std::string log_text(const LandscapeState& state);

}  // namespace edgeland::detail
