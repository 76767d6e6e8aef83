#pragma once
// Typed errors: every public operation that rejects its input throws one of these, with the
// offending indices and location as fields, never only inside the message text.
#include <cstddef>
#include <stdexcept>
#include <string>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/point.hpp"

namespace edgeland {

class EDGELAND_EXPORT Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A coordinate outside [-kCoordBound, kCoordBound].
class EDGELAND_EXPORT CoordinateOutOfRange : public Error {
 public:
  CoordinateOutOfRange(std::size_t polygon, std::size_t vertex, Point64 where);
  std::size_t polygon;
  std::size_t vertex;
  Point64 where;
};

}  // namespace edgeland
