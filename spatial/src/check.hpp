#pragma once
// The invariants of spatial/README.md as checks: per cell, per inner node, and over the whole
// landscape. Checked mode runs the first two on what an edit made; Landscape::check() runs all.
#include <string>
#include <vector>

#include "changes.hpp"
#include "edgeland/spatial/errors.hpp"
#include "edgeland/spatial/landscape_state.hpp"
#include "edgeland/spatial/types.hpp"
#include "node.hpp"

namespace edgeland::detail {

// Problems of one cell (I1, I2, I3, I5, the grid's shape and its own sums), each a line naming
// the cell.
void check_cell(const Node& cell, const LandscapeConfig& config,
                std::vector<std::string>& problems);
// The same but for what holds by construction for a cell just made by make_cell from a
// validated set: I2, I3, I5, the grid's shape and its materials (load() runs this per cell).
void check_cell_content(const Node& cell, const LandscapeConfig& config,
                        std::vector<std::string>& problems);
// Problems of one inner node (I4, I7, I8, the grid's shape) with respect to its children.
void check_inner(const Node& node, const LandscapeConfig& config,
                 std::vector<std::string>& problems);

// What is wrong with the tree an edit built from `before` (empty: nothing). old_next_id: the
// landscape's next id before the edit.
std::string check_edit(const LandscapeState& before, const NodePtr& new_root,
                       const Changes& changes, PolygonId old_next_id);

// Every invariant over a whole state (Landscape::check()).
LandscapeReport check_all(const LandscapeState& s);

// The error of a failed check or an internal failure during an edit: carries the landscape
// before the edit (save file) and a log replaying it, followed by the edit's own line.
LandscapeInternalError internal_error(const LandscapeState& s, const std::string& what,
                                      const std::string& log_line);

}  // namespace edgeland::detail
