#pragma once
// The edit-log recorder (README.md "Landscape edit logs"): the line each edit writes, and the
// log kept as a persistent list of lines so that copies of a recording landscape share it.
#include <memory>
#include <span>
#include <string>

#include "edgeland/spatial/landscape.hpp"

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

// "carve WKT", "fill M WKT", "fill_empty M WKT", "replace FROM TO WKT", "relabel [FROM TO]...
// WKT" (the pairs where the map changes a material, ascending), each ending in '\n'.
std::string carve_line(const PolygonSet& shape);
std::string fill_line(const PolygonSet& shape, Material m);
std::string fill_empty_line(const PolygonSet& shape, Material m);
std::string replace_line(const PolygonSet& shape, Material from, Material to);
std::string relabel_line(const PolygonSet& shape, const MaterialMap& map);
// "batch EDIT | EDIT | ...": every edit of a batch (Landscape::apply_batch) as its own line
// would say it without the line break (its kind's line when its map has its kind's form, else
// relabel's), in order, separated by " | " (no WKT holds a '|').
std::string batch_line(std::span<const Edit> edits);
// "world X0 Y0 X1 Y1[ M]".
std::string world_line(const Box64& world, Material fill);

// A log that replays to the landscape's regions: the world line when nothing was edited since
// it was made, else the world line and one fill per material.
std::string state_log(const LandscapeState& s);
// The recorded log if the landscape records one, else state_log.
std::string replay_log(const LandscapeState& s);

// The state with `line` appended to its log.
void append_log(LandscapeState& state, const std::string& line);
std::string log_text(const LandscapeState& state);

}  // namespace edgeland::detail
