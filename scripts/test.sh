#!/usr/bin/env bash
# The whole test suite: unit, property and CLI tests, the install/consumer test, and the
# proofs and exhaustive checks (label `proofs`). This is the README's test command and the
# first step of .ci/run. Run from anywhere; builds in build/test.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EDGELAND_BUILD_DIR:-build/test}"
jobs="${EDGELAND_JOBS:-$(nproc)}"

# Optimised, but with assert() on (RelWithDebInfo without -DNDEBUG) and the checked build's
# overflow trap on every kernel operation (EDGELAND_CHECKED). -g1 (line tables, no variables)
# names the file and line in a backtrace and compiles the template-heavy tests 15% faster than
# -g; configure your own build with -g to step through it in a debugger.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1" \
  -DEDGELAND_CHECKED=ON
cmake --build "$build" -j "$jobs"
ctest --test-dir "$build" --output-on-failure -j "$jobs"
