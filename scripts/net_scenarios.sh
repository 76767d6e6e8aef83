#!/usr/bin/env bash
# The long forms of the multi-process scenarios of issue 37 (tests/net/scenarios.py; ctest runs
# short ones under the labels load, net, crash and two_servers): 16 clients for 60 s at 10 edits
# a second, the rejoin and hostile runs for 30 s, 50 kills of the SQLite writer, two servers on
# one PostgreSQL store for 30 s. Each prints one JSON line of figures; exit 1 if any fails.
# Usage: scripts/net_scenarios.sh [BUILD_DIR]   (a build of scripts/test.sh, default build/test)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/test}"
edgeland="$build/cli/edgeland"
run=(/usr/bin/python3 tests/net/scenarios.py)
status=0
"${run[@]}" load --edgeland "$edgeland" --clients 16 --seconds 60 --rate 10 || status=1
"${run[@]}" rejoin --edgeland "$edgeland" --seconds 30 || status=1
"${run[@]}" hostile --edgeland "$edgeland" --seconds 30 || status=1
"${run[@]}" crash --edgeland "$edgeland" --rounds 50 || status=1
"${run[@]}" two-servers --edgeland "$edgeland" --seconds 30 --rate 20 \
  --store-tests "$build/tests/net/postgres_store_tests" || status=1
exit $status
