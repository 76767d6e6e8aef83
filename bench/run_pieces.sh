#!/usr/bin/env bash
# Builds edgeland_pieces_bench (Release, in build/bench-pieces), runs every benchmark in its own
# process with a time limit (a CGAL partition that takes too long on a large polygon loses only
# that row), collects the JSON and prints the Markdown tables of bench/README.md ("Triangulation
# and convex pieces"). About 10 minutes on the 2-core machine.
#
# Environment (all optional):
#   EDGELAND_PIECES_BUILD_DIR   build directory (default: build/bench-pieces)
#   EDGELAND_PIECES_FILTER      regex over benchmark names (default: everything)
#   EDGELAND_PIECES_TIMEOUT_S   seconds per benchmark process (default: 300)
#   EDGELAND_PIECES_DEMO_EDITS  edits of the demo world (default: 6000)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=${EDGELAND_PIECES_BUILD_DIR:-$repo/build/bench-pieces}
filter=${EDGELAND_PIECES_FILTER:-.}
timeout_s=${EDGELAND_PIECES_TIMEOUT_S:-300}
out=$build/pieces-results

cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DEDGELAND_BUILD_BENCH=ON \
  -DEDGELAND_BUILD_TESTS=OFF -DEDGELAND_BUILD_PROOFS=OFF >&2
cmake --build "$build" --target edgeland_pieces_bench -j2 >&2
rm -rf "$out" && mkdir -p "$out"
cp "$build/bench/edgeland_pieces_bench" "$out/"
bench="$out/edgeland_pieces_bench"
"$bench" --benchmark_list_tests "--benchmark_filter=$filter" | while read -r name; do
  file="$out/$(echo "$name" | tr '/' '_').json"
  if ! timeout "$timeout_s" "$bench" "--benchmark_filter=^${name}\$" --benchmark_min_time=0.5 \
      "--benchmark_out=$file" --benchmark_out_format=json >/dev/null 2>&1; then
    echo "{\"failed\": {\"name\": \"$name\", \"why\": \"over ${timeout_s} s or crashed\"}}" >"$file"
  fi
  echo "$name done" >&2
done
python3 "$repo/bench/pieces_table.py" "$out" | tee "$out/tables.md"
