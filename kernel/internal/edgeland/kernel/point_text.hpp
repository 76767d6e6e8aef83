#pragma once
// A point as text for messages, "(x y)", for the kernel's errors and clip's stage checkers.
// Appended piece by piece: `"(" + std::to_string(...)` draws a false -Wrestrict warning from
// GCC 12 at -O2 and above (GCC bug 105651).
#include <string>

#include "edgeland/kernel/point.hpp"

namespace edgeland::detail {

inline std::string point_text(Point64 p) {
  std::string out = "(";
  out += std::to_string(p.x);
  out += ' ';
  out += std::to_string(p.y);
  out += ')';
  return out;
}

}  // namespace edgeland::detail
