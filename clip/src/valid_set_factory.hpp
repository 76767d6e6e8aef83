#pragma once
// The one way library code makes a ValidSet without validating it again: from an operation's
// output (valid by clip.hpp's guarantee, re-checked in checked mode).
#include <utility>

#include "edgeland/clip/valid_set.hpp"

namespace edgeland {

struct ValidSetFactory {
  static ValidClipResult from(ClipResult r) {
    ValidSet set(std::move(r.polygons), ValidSet::Trusted{});
    set.canonical_ = true;  // every output is in canonical form (clip.hpp)
    set.collinear_free_ = true;
    return {std::move(set), r.stats};
  }
  static bool canonical(const ValidSet& s) { return s.canonical_; }
  static bool collinear_free(const ValidSet& s) { return s.collinear_free_; }
};

}  // namespace edgeland
