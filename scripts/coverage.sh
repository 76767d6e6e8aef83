#!/usr/bin/env bash
# scripts/coverage.sh: line and branch coverage of kernel/, clip/ and spatial/ by the test suite.
#
# Builds the suite with gcc --coverage (Debug, -O0, the checked kernel as in scripts/test.sh)
# in build/coverage (EDGELAND_BUILD_DIR overrides), runs ctest (all labels but the install
# test; extra ctest options such as `-L 'kernel|clip|spatial'` may be given as arguments), and
# reports with gcovr:
#   build/coverage/coverage.txt          per-file table (lines; column "Missing")
#   build/coverage/coverage.json         the same data (gcovr --add-tracefile reads it)
#   build/coverage/html/index.html       annotated sources
# and on stdout the summary of each folder (kernel/, clip/, spatial/) and of all three. Branch
# figures exclude the branches the compiler adds for exceptions (--exclude-throw-branches) and
# ones it proves unreachable.
#
# EDGELAND_COVERAGE_TARGETS (optional): build only these targets, for a figure of one folder from
# the tests that reach it, e.g. spatial/:
#   EDGELAND_COVERAGE_TARGETS="spatial_tests spatial_memory_tests game_tests io_tests \
#     edgeland_cli regress_replay" scripts/coverage.sh -L '^(spatial|game|io|cli|regress)$'
# (tests whose executables were not built then fail and count nothing). Compile without ccache:
# its base_dir makes the recorded source paths relative, which gcovr cannot resolve.
#
# Counted: the objects of the executables the chosen tests ran, and the three libraries. Left
# out: executables no chosen test ran (their copies of our inline header code would count as
# unreached lines), and determinism_O0/O3, which compile the library sources a second and third
# time (at -O3 gcc ascribes code to lines that hold none, such as `using` declarations).
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EDGELAND_BUILD_DIR:-build/coverage}"
jobs="${EDGELAND_JOBS:-$(nproc)}"

cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=g++ -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS="--coverage -O0" -DCMAKE_EXE_LINKER_FLAGS=--coverage \
  -DCMAKE_SHARED_LINKER_FLAGS=--coverage -DEDGELAND_CHECKED=ON >/dev/null
if [ -n "${EDGELAND_COVERAGE_TARGETS:-}" ]; then
  # shellcheck disable=SC2086 # a list of target names
  cmake --build "$build" -j "$jobs" --target ${EDGELAND_COVERAGE_TARGETS}
else
  cmake --build "$build" -j "$jobs"
fi
find "$build" -name '*.gcda' -delete  # counts of this run only
# install.consumer is left out: it builds a separate project against the installed static
# libraries, which carry gcov references that project does not link (--coverage is ours only).
ctest --test-dir "$build" -j "$jobs" --output-on-failure -E '^install\.consumer$' "$@" || echo "coverage.sh: some tests failed (coverage still reported)" >&2

# Object directories to leave out (see above); a directory regex for gcovr, absolute.
skipped=()
while IFS= read -r dir; do
  case "$dir" in
    */edgeland_kernel.dir | */edgeland_clip.dir | */edgeland_spatial.dir) continue ;;
  esac
  if [[ "$dir" == */determinism_O[03].dir ]] ||
    [[ -z "$(find "$dir" -name '*.gcda' -print -quit)" ]]; then
    skipped+=(--exclude-directories "$(printf '%s' "$dir" | sed 's/[].[^$*+?(){}|\\]/\\&/g')\$")
  fi
done < <(find "$(cd "$build" && pwd -P)" -type d -name '*.dir')

mkdir -p "$build/html"
gcovr --root . --object-directory "$build" --filter 'kernel/' --filter 'clip/' --filter 'spatial/' \
  --exclude-throw-branches --exclude-unreachable-branches "${skipped[@]}" \
  --json "$build/coverage.json" --txt "$build/coverage.txt" --html-details "$build/html/index.html"
# Per folder from the JSON (no second gcov pass), then all three.
for folder in kernel/ clip/ spatial/ ''; do
  echo "${folder:-kernel/ clip/ spatial/ together}:"
  gcovr --root . --add-tracefile "$build/coverage.json" ${folder:+--filter "$folder"} \
    --print-summary --txt /dev/null | sed 's/^/  /'
done | tee "$build/coverage-summary.txt"
echo "coverage.sh: ${SECONDS} s; per-file table in $build/coverage.txt, annotated sources in" \
  "$build/html/index.html"
