#pragma once
// How the stage checkers (stage_checks.hpp) write points and segments into their messages:
// WKT-like, "(x y)" and "(x y)-(x y)", so a failing check can be pasted into a bug report.
#include <string>

#include "edgeland/kernel/point_text.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::detail {

inline std::string text(Point64 p) { return point_text(p); }

inline std::string text(const Segment& s) { return text(s.a) + "-" + text(s.b); }

}  // namespace edgeland::detail
