#!/bin/sh
# write_failure_test.sh EDGELAND ARGS...: runs `EDGELAND ARGS...` with standard output on
# /dev/full (every write fails with ENOSPC, as on a full disk) and requires exit status 2 and
# exactly one line on standard error saying the output could not be written.
edgeland="$1"
shift
err=$("$edgeland" "$@" 2>&1 >/dev/full)
status=$?
lines=$(printf '%s\n' "$err" | wc -l)
if [ "$status" -ne 2 ] || [ "$lines" -ne 1 ] || ! printf '%s' "$err" | grep -q "cannot write"; then
  echo "expected exit 2 and one line about the failed write; got exit $status, stderr:"
  printf '%s\n' "$err"
  exit 1
fi
echo "ok: exit 2, $err"
