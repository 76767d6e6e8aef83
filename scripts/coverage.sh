#!/usr/bin/env bash
# scripts/coverage.sh: line and branch coverage of kernel/ and clip/ by the test suite.
#
# Builds the suite with gcc --coverage (Debug, -O0, the checked kernel as in scripts/test.sh)
# in build/coverage (EDGELAND_BUILD_DIR overrides), runs ctest (all labels but the install
# test; extra ctest options such as `-L clip` may be given as arguments), and reports with gcovr:
#   build/coverage/coverage.txt          per-file table (lines and branches)
#   build/coverage/html/index.html       annotated sources
# and the two summary lines on stdout. Branch figures exclude the branches the compiler adds
# for exceptions (--exclude-throw-branches) and ones it proves unreachable.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EDGELAND_BUILD_DIR:-build/coverage}"
jobs="${EDGELAND_JOBS:-$(nproc)}"

cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=g++ -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS="--coverage -O0" -DCMAKE_EXE_LINKER_FLAGS=--coverage \
  -DCMAKE_SHARED_LINKER_FLAGS=--coverage -DEDGELAND_CHECKED=ON >/dev/null
cmake --build "$build" -j "$jobs"
find "$build" -name '*.gcda' -delete  # counts of this run only
# install.consumer is left out: it builds a separate project against the installed static
# libraries, which carry gcov references that project does not link (--coverage is ours only).
ctest --test-dir "$build" -j "$jobs" --output-on-failure -E '^install\.consumer$' "$@" || echo "coverage.sh: some tests failed (coverage still reported)" >&2

mkdir -p "$build/html"
gcovr_common=(--root . --object-directory "$build" --filter 'kernel/' --filter 'clip/'
  --exclude-throw-branches --exclude-unreachable-branches)
gcovr "${gcovr_common[@]}" --txt "$build/coverage.txt" --html-details "$build/html/index.html" \
  --print-summary | tee "$build/coverage-summary.txt"
echo "coverage.sh: per-file table in $build/coverage.txt, annotated sources in $build/html/index.html"
