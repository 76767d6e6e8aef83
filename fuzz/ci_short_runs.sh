#!/usr/bin/env bash
# CI's fuzz step (.ci/run, last step): every fuzz target for a short budget through
# fuzz/campaign (builds build/fuzz with clang 14 + ASan + UBSan, or uses the build given by
# EDGELAND_FUZZ_BUILD_DIR: CI passes build/sanitize, which scripts/test_sanitizers.sh configures
# with the fuzz targets), then the whole regression corpus and the seed corpora run once
# through the sanitized fuzz binaries. (The gcc build replays the same corpus in ctest, label
# `regress`; the sanitizer pass leaves the seed replay to this step.)
# EDGELAND_FUZZ_CI_SECONDS sets the budget per target (default 20). Exit 1 on any crash.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${EDGELAND_FUZZ_CI_SECONDS:-20}"
build="${EDGELAND_FUZZ_BUILD_DIR:-build/fuzz}"
passed=0 failed=0
for target in clip_pair clip_sequence normalize parse edit_sequence load; do
  if EDGELAND_FUZZ_RECORD=0 fuzz/campaign "$target" "$seconds"; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
done
for target in clip_pair clip_sequence normalize parse edit_sequence load; do
  dirs=()
  for dir in "tests/regress/$target" "fuzz/corpus/$target"; do
    [ -d "$dir" ] && dirs+=("$dir")
  done
  # -runs=0: execute every given input once, no mutation.
  if "$build/fuzz/fuzz_$target" -runs=0 -timeout=30 "${dirs[@]}" >"$build/ci-replay-$target.log" 2>&1; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "fuzz/ci_short_runs.sh: replaying the corpus of $target failed:" >&2
    tail -30 "$build/ci-replay-$target.log" >&2
  fi
done
echo "fuzz: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
