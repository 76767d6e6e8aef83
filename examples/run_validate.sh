#!/usr/bin/env bash
# Runs `edgeland validate` on every sample shape in this folder and prints `file: verdict`.
# Usage: examples/run_validate.sh [path/to/edgeland]   (default: build/release/cli/edgeland)
# The verdict is the command's one line (stdout for valid/invalid, stderr when unreadable).
# Exits non-zero only if the command itself fails: a status other than 0, 1 or 2.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
edgeland="${1:-$here/../build/release/cli/edgeland}"
status=0
for file in "$here"/*.wkt; do
  rc=0
  verdict="$("$edgeland" validate "$file" 2>&1)" || rc=$?
  printf '%s: %s\n' "$(basename "$file")" "${verdict#edgeland validate: "$file": }"
  if [ "$rc" -gt 2 ]; then
    echo "  ^ unexpected exit status $rc" >&2
    status=1
  fi
done
exit "$status"
