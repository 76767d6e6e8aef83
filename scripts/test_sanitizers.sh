#!/usr/bin/env bash
# The test suite again, built with clang++-14 under AddressSanitizer + UndefinedBehaviorSanitizer
# (EDGELAND_SANITIZE; any report aborts the test). The Z3 proofs (label `proofs`) are left out:
# they check the arithmetic symbolically, so running them under sanitizers adds nothing.
# Second step of .ci/run. Run from anywhere; builds in build/sanitize.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EDGELAND_BUILD_DIR:-build/sanitize}"
jobs="${EDGELAND_JOBS:-$(nproc)}"

cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DEDGELAND_SANITIZE=ON -DEDGELAND_CHECKED=ON -DEDGELAND_BUILD_PROOFS=OFF
cmake --build "$build" -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$build" --output-on-failure -j "$jobs"
