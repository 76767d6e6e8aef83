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
passed=0 failed=0
for target in clip_pair clip_sequence normalize parse edit_sequence load; do
  if EDGELAND_FUZZ_RECORD=0 fuzz/campaign "$target" "$seconds"; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
done
echo "fuzz: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
