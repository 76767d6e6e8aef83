// ValidSet (valid_set.hpp): made by validating, recording whether it is free of collinear
// consecutive vertices (the pipeline then tests only the vertices an operation creates).
#include "edgeland/clip/valid_set.hpp"

#include "canonical.hpp"
#include "pipeline.hpp"

namespace edgeland {

ValidSet::ValidSet(PolygonSet set, Operand which) : set_(std::move(set)) {
  detail::require_valid(set_, which);
  collinear_free_ = detail::collinear_free(set_);
}

ValidSet subset(const ValidSet& set, std::span<const std::size_t> members) {
  PolygonSet out;
  out.reserve(members.size());
  for (std::size_t k = 0; k < members.size(); ++k) {
    if (members[k] >= set.set_.size() || (k > 0 && members[k] <= members[k - 1]))
      throw ArgumentOutOfRange("members", static_cast<std::int64_t>(members[k]),
                               k > 0 ? static_cast<std::int64_t>(members[k - 1]) + 1 : 0,
                               static_cast<std::int64_t>(set.set_.size()) - 1);
    out.push_back(set.set_[members[k]]);
  }
  ValidSet part(std::move(out), ValidSet::Trusted{});
  part.canonical_ = set.canonical_;
  part.collinear_free_ = set.collinear_free_;
  return part;
}

}  // namespace edgeland
