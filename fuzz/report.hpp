#pragma once
// What a fuzz target does with a Finding: print it (with its replayable log) and abort, which
// libFuzzer records as a crash and saves the input.
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "decoders.hpp"

namespace edgeland::fuzz {

inline void abort_on(const std::optional<Finding>& finding) {
  if (!finding) return;
  std::fprintf(stderr, "==edgeland finding== %s\n", finding->what.c_str());
  if (!finding->log.empty()) {
    std::fprintf(stderr, "==edgeland replay log==\n%s==end of log==\n", finding->log.c_str());
  }
  std::abort();
}

}  // namespace edgeland::fuzz
