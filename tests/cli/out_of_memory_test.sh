#!/bin/sh
# out_of_memory_test.sh EDGELAND DIR: runs `EDGELAND validate` on 100,000 squares (4.4 MB,
# written to DIR) with the address space limited to 60 MB, so that an allocation fails, and
# requires exit status 4 and the one line "edgeland: out of memory" (issue 16: it was exit 3,
# "internal error: std::bad_alloc", the status reserved for bugs).
edgeland="$1"
input="$2/hundred_thousand_squares.wkt"
awk 'BEGIN { printf "MULTIPOLYGON (";
             for (i = 0; i < 100000; i++) printf "%s((0 0, 10 0, 10 10, 0 10, 0 0))", (i ? ", " : "");
             print ")" }' >"$input" || exit 1
err=$( (ulimit -v 60000 && "$edgeland" validate "$input") 2>&1 >/dev/null)
status=$?
if [ "$status" -ne 4 ] || [ "$err" != "edgeland: out of memory" ]; then
  echo "expected exit 4 and 'edgeland: out of memory'; got exit $status, stderr:"
  printf '%s\n' "$err"
  exit 1
fi
echo "ok: exit 4, $err"
