#pragma once
// A landscape's state for the stage tests, read back from its save file (save_load.hpp): the
// same tree, ids and next id (the same state_hash), with no door into the Landscape. The load
// counts one edit and no log (Landscape::load).
#include <sstream>

#include "edgeland/spatial/landscape.hpp"
#include "save_load.hpp"

namespace edgeland::test {

inline detail::LandscapeState state_of(const Landscape& l) {
  std::stringstream bytes;
  l.save(bytes);
  return detail::load_state(bytes, l.limits());
}

}  // namespace edgeland::test
