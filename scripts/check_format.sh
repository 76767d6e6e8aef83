#!/usr/bin/env bash
# Fails (exit 1) when a tracked C++ file differs from what clang-format-14 makes of it under the
# repository's .clang-format, and lists those files. With --fix, formats them in place instead.
# .ci/run runs it after the test command (which installs clang-format-14).
set -euo pipefail
cd "$(dirname "$0")/.."
format=$(command -v clang-format-14 || true)
if [ -z "$format" ]; then
  echo "scripts/check_format.sh: clang-format-14 not found (apt-get install -y clang-format-14)" >&2
  exit 2
fi
# The tracked files; outside a git checkout (an exported tree), every C++ file but build output.
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
else
  mapfile -t files < <(find . -path './build*' -prune -o -path './.git' -prune -o \
    \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -type f -print | sed 's|^\./||' | sort)
fi
if [ "${1:-}" = "--fix" ]; then
  "$format" -i "${files[@]}"
  exit 0
fi
# One clang-format per file, on every core.
mapfile -t differ < <(printf '%s\0' "${files[@]}" | xargs -0 -P "$(nproc)" -n 16 sh -c \
  'for f; do "$0" --dry-run --Werror "$f" >/dev/null 2>&1 || echo "$f"; done' "$format" | sort)
if [ "${#differ[@]}" -gt 0 ]; then
  echo "Not formatted by clang-format-14 (scripts/check_format.sh --fix formats them):" >&2
  printf '  %s\n' "${differ[@]}" >&2
  exit 1
fi
echo "clang-format: all ${#files[@]} C++ files formatted"
