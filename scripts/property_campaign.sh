#!/usr/bin/env bash
# scripts/property_campaign.sh CASES [SEED]
#
# A long RapidCheck campaign: runs the kernel and clip properties (every RC_GTEST_PROP in
# tests/kernel/ and tests/clip/, in kernel_tests and clip_tests) with RC_PARAMS="max_success=CASES seed=SEED" (RapidCheck reads RC_PARAMS from
# the environment; any other RC_PARAMS options you export are kept). Without SEED a random one
# is drawn and printed, so every campaign can be repeated exactly.
#
# On a failure RapidCheck prints the shrunk counterexample (the tests print their operands
# as WKT: "A = MULTIPOLYGON ...", "B = ...") and an RC_PARAMS="reproduce=..." line. This
# script also turns every WKT operand pair it finds in the failure output into a replayable
# continuous-clip log (`set A`, then each operation with B) under
# <build>/property-campaign/, and prints it: `edgeland replay --check FILE` re-runs it.
#
# Builds in build/test like scripts/test.sh (EDGELAND_BUILD_DIR overrides). Exit status:
# 0 all properties held, 1 a property failed.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 1 ] || [ $# -gt 2 ] || ! [[ "$1" =~ ^[0-9]+$ ]]; then
  echo "usage: scripts/property_campaign.sh CASES [SEED]" >&2
  exit 2
fi
cases="$1"
seed="${2:-$(od -An -N4 -tu4 /dev/urandom | tr -d ' ')}"
build="${EDGELAND_BUILD_DIR:-build/test}"
jobs="${EDGELAND_JOBS:-$(nproc)}"
out="$build/property-campaign"

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1" \
  -DEDGELAND_CHECKED=ON >/dev/null
cmake --build "$build" -j "$jobs" --target kernel_tests clip_tests edgeland_cli >/dev/null
mkdir -p "$out"

export RC_PARAMS="${RC_PARAMS:+$RC_PARAMS }max_success=$cases seed=$seed"
echo "property campaign: RC_PARAMS=\"$RC_PARAMS\""

# Every "A = <WKT>" (or "subject = <WKT>") line followed by "B = <WKT>" (or "clip = ") becomes
# one log with the four operations; a lone A becomes a one-line `set` log.
write_logs() {
  local report="$1" name="$2"
  awk -v dir="$out" -v name="$name" '
    function flush() {
      if (a == "") return
      file = sprintf("%s/%s-%d.log", dir, name, ++n)
      print "# " name " counterexample " n " (scripts/property_campaign.sh)" > file
      if (b == "") print "set " a > file
      split("union intersection difference xor", ops, " ")
      for (i = 1; b != "" && i <= 4; ++i) { print "set " a > file; print ops[i] " " b > file }
      close(file); print file
      a = ""; b = ""
    }
    match($0, /^[[:space:]]*(A|subject) = (MULTI)?POLYGON/) { flush(); a = substr($0, index($0, "= ") + 2); next }
    match($0, /^[[:space:]]*(B|clip) = (MULTI)?POLYGON/) { b = substr($0, index($0, "= ") + 2); flush(); next }
    END { flush() }' "$report"
}

# Only the properties (RC_GTEST_PROP / RC_GTEST_FIXTURE_PROP), found in the test sources:
# the example-based tests do not depend on the case count.
properties() {
  grep -ohE 'RC_GTEST(_FIXTURE)?_PROP\(\s*[A-Za-z0-9_]+\s*,\s*[A-Za-z0-9_]+' "tests/$1"/*.cpp |
    sed -E 's/.*\(\s*([A-Za-z0-9_]+)\s*,\s*([A-Za-z0-9_]+)$/\1.\2/' | paste -sd: -
}

status=0
for suite in kernel_tests clip_tests; do
  binary="$(find "$build/tests" -name "$suite" -type f -perm -u+x | head -1)"
  report="$out/$suite.txt"
  filter="$(properties "${suite%_tests}")"
  echo "== $suite: $(tr ':' '\n' <<<"$filter" | wc -l) properties (max_success=$cases, seed=$seed)"
  start=$SECONDS
  if "$binary" --gtest_filter="$filter" >"$report" 2>&1; then
    echo "   passed in $((SECONDS - start)) s: $(grep -cE '^\[       OK \]' "$report") properties"
    continue
  fi
  status=1
  echo "   FAILED after $((SECONDS - start)) s; full output: $report"
  grep -E '^\[  FAILED  \]|Falsifiable|reproduce=|^Using configuration' "$report" | sort -u | sed 's/^/   /'
  # The shrunk counterexamples and messages (as WKT) of the failed properties.
  grep -E '^[[:space:]]*(A|B|subject|clip|output|got|want) = ' "$report" | sed 's/^/   /' | head -40
  for log in $(write_logs "$report" "$suite"); do
    echo "   replayable log: $log   (edgeland replay --check $log)"
    sed 's/^/     /' "$log"
  done
done
exit "$status"
