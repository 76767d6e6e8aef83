#pragma once
// Save files of a landscape's state (save_format.hpp): Landscape::save and Landscape::load are
// these, and an internal error carries the state before the failed edit as a save file.
#include <iosfwd>
#include <string>

#include "edgeland/spatial/landscape_state.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland::detail {

void save_state(const LandscapeState& state, std::ostream& out);
// Throws LoadError or LimitExceeded (Landscape::load).
LandscapeState load_state(std::istream& in, const LandscapeLimits& limits);
// The stream's bytes, at most what a file of a world within the limits can take (LoadError
// beyond, or when the stream fails).
std::string read_stream(std::istream& in, const LandscapeLimits& limits);

}  // namespace edgeland::detail
