#!/usr/bin/env bash
# CI's fuzz step (.ci/run, last step): every fuzz target for a short budget through
# fuzz/campaign (builds build/fuzz with clang 14 + ASan + UBSan, or uses the build given by
# EDGELAND_FUZZ_BUILD_DIR: CI passes build/sanitize, which scripts/test_sanitizers.sh configures
# with the fuzz targets). Each campaign first runs every seed of fuzz/corpus/TARGET and every
# saved input of tests/regress/TARGET once through the sanitized binary (libFuzzer's start), so
# the seeds and the regression corpus are replayed here too; a separate replay pass ran them
# all a second time. (The gcc build replays the same files in ctest, label `regress`.)
# EDGELAND_FUZZ_CI_SECONDS sets the budget per target (default 20; the start is not counted
# against it). Exit 1 on any crash.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${EDGELAND_FUZZ_CI_SECONDS:-20}"
lanes="${EDGELAND_JOBS:-$(nproc)}"
# One campaign per core at a time (each is one libFuzzer process), longest start first: the
# clip targets' starts replay thousands of seeds (clip_sequence about 2.5 minutes under ASan on
# CI's machine), so two lanes take about half the time of one. Each campaign prints one summary
# line and keeps its log in the build directory.
results="$(mktemp -d)"
trap 'rm -rf "$results"' EXIT
targets=(clip_sequence clip_pair normalize parse edit_sequence game_sequence load polygon_pieces delta
  int128_portable net_message)
printf '%s\n' "${targets[@]}" |
  xargs -P "$lanes" -I{} sh -c \
    'if EDGELAND_FUZZ_RECORD=0 fuzz/campaign "$1" "$2"; then touch "$3/$1.passed"; else touch "$3/$1.failed"; fi' \
    _ {} "$seconds" "$results"
passed=$(find "$results" -name '*.passed' | wc -l)
failed=$((${#targets[@]} - passed))
[ "$failed" -eq 0 ] || echo "fuzz: failed: $(cd "$results" && ls ./*.failed 2>/dev/null | sed 's|^./||; s|.failed$||' | tr '\n' ' ')"
echo "fuzz: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
