#pragma once
// The landscape's private state for spatial/src: the one door in (the Landscape's only friend).
#include "edgeland/spatial/landscape.hpp"

namespace edgeland {

struct LandscapeAccess {
  static const detail::LandscapeState& state(const Landscape& l) noexcept { return l.s_; }
  // Commits a whole new state (an edit's last step, a load's result).
  static void commit(Landscape& l, detail::LandscapeState next) noexcept { l.s_ = std::move(next); }
  static Landscape make(detail::LandscapeState state) { return Landscape(std::move(state)); }
};

}  // namespace edgeland
