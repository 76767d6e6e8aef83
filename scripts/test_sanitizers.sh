#!/usr/bin/env bash
# The test suite again, built with clang++-14 under AddressSanitizer + UndefinedBehaviorSanitizer
# (EDGELAND_SANITIZE; any report aborts the test). Left out, to keep CI's time:
# - the Z3 proofs (label `proofs`): they check the arithmetic symbolically, so sanitizers add
#   nothing;
# - the bounded-exhaustive clip checks (label `exhaustive`): thousands of tiny overlays through
#   the same code paths the property tests drive under the sanitizers; the gcc pass runs them;
# - the replay of the fuzz seed corpora (`regress.seeds.*`): CI's fuzz step replays the same
#   files through the sanitized fuzz binaries;
# - the browser playground (label `web`): Emscripten builds it into WebAssembly whatever the
#   host build's flags, so the gcc pass's build and browser test are the same test.
# - the multi-process load, crash and two-server scenarios (labels `load`, `crash`,
#   `two_servers`): they measure and kill processes, and run the same code the in-process
#   net_tests and store_tests run here; the rejoin and hostile scenarios (label `net`) stay, so
#   the server meets hostile bytes under the sanitizers too.
# The build also holds the libFuzzer targets (same compiler and flags as fuzz/campaign's), so
# CI's fuzz step (EDGELAND_FUZZ_BUILD_DIR=build/sanitize) does not compile the library again.
# -gline-tables-only: the sanitizers' reports need file and line only (a quarter less compile time
# than -g on the CGAL oracle). Second step of .ci/run. Run from anywhere; builds in build/sanitize.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EDGELAND_BUILD_DIR:-build/sanitize}"
jobs="${EDGELAND_JOBS:-$(nproc)}"

cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
  -DEDGELAND_SANITIZE=ON -DEDGELAND_CHECKED=ON -DEDGELAND_BUILD_PROOFS=OFF -DEDGELAND_BUILD_FUZZ=ON
cmake --build "$build" -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$build" --output-on-failure -j "$jobs" -LE 'exhaustive|web|load|crash|two_servers' -E '^regress\.seeds\.'
