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

}  // namespace edgeland
