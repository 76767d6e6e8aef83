#pragma once
// Two tiers of internal checks (STYLE.md, after Box2D's asserts and *_Validate checkers).
//
// * EDGELAND_ASSERT(condition, stage, message): a cheap precondition inside a stage. On in
//   every test build: when EDGELAND_CHECKED is nonzero (the checked build) or NDEBUG is not
//   defined (debug builds). Otherwise it compiles to nothing and `condition` is not evaluated
//   (it is still parsed, so a variable used only in an assert stays "used").
// * fail_stage(stage, what): always on, for the invariants a stage tests on every run (and
//   for the stage checkers of the checked build, clip/src/stage_checks.hpp).
//
// Both throw std::logic_error("<stage>: <what> (<file>:<line>)"). The pipeline's `guarded`
// (clip/src/pipeline.hpp) turns any std::logic_error into the always-on InternalError, which
// carries the inputs as WKT; the text then names the stage that failed, the broken rule and
// where it was found, which is what a bug report needs. Library code prints nothing.
#include <string>

#include "edgeland/kernel/export.hpp"

namespace edgeland::detail {

// Throws std::logic_error("<stage>: <what> (<file>:<line>)"), the file without its directory
// (file names are unique within a part of the library, and the text stays the same on every
// machine). `file` and `line` default to the caller's position: __builtin_FILE / __builtin_LINE,
// which gcc and clang 14 (the sanitizer build, Emscripten) both have, where std::source_location
// needs clang 15 with libstdc++.
[[noreturn]] EDGELAND_EXPORT void fail_stage(const char* stage, const std::string& what,
                                             const char* file = __builtin_FILE(),
                                             int line = __builtin_LINE());

}  // namespace edgeland::detail

#if (defined(EDGELAND_CHECKED) && EDGELAND_CHECKED) || !defined(NDEBUG)
#define EDGELAND_ASSERTS_ENABLED 1
#else
#define EDGELAND_ASSERTS_ENABLED 0
#endif

#if EDGELAND_ASSERTS_ENABLED
// The message is built only when the condition fails.
#define EDGELAND_ASSERT(condition, stage, message)                        \
  do {                                                                    \
    if (!(condition)) ::edgeland::detail::fail_stage((stage), (message)); \
  } while (false)
#else
// sizeof does not evaluate its operand: no cost, no unused-variable warnings.
#define EDGELAND_ASSERT(condition, stage, message) \
  do {                                             \
    static_cast<void>(sizeof(!(condition)));       \
  } while (false)
#endif
