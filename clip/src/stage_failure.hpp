#pragma once
// A broken invariant inside a pipeline stage: std::logic_error naming the stage, which the
// public operations turn into InternalError (pipeline.hpp, guarded).
#include <stdexcept>
#include <string>

namespace edgeland::detail {

[[noreturn]] inline void fail_stage(const char* stage, const char* what) {
  throw std::logic_error(std::string(stage) + ": " + what);
}

}  // namespace edgeland::detail
