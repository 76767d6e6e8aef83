#pragma once
// Save files of a landscape's state (save_format.hpp): Landscape::save and Landscape::load are
// these, and an internal error carries the state before the failed edit as a save file.
#include <iosfwd>

#include "edgeland/spatial/landscape_state.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland::detail {

void save_state(const LandscapeState& state, std::ostream& out);
// Throws LoadError or LimitExceeded (Landscape::load).
LandscapeState load_state(std::istream& in, const LandscapeLimits& limits);

}  // namespace edgeland::detail
