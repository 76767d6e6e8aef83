#!/usr/bin/env bash
# Builds edgeland_bench (Release), runs every benchmark in its own process (a peer that
# crashes or hangs loses only that benchmark) with --benchmark_format=json, and prints the
# Markdown ratio tables of bench/README.md (ratio_table.py).
#
# Environment (all optional):
#   EDGELAND_BENCH_BUILD_DIR      build directory (default: build-bench in the repository)
#   EDGELAND_BENCH_OUT            where the JSON files go (default: BUILD_DIR/bench-results)
#   EDGELAND_BENCH_FILTER         regex over benchmark names (default: everything)
#   EDGELAND_BENCH_TIMEOUT_S      wall-clock limit per benchmark process (default 3600)
#   EDGELAND_BENCH_CARVE_OPS      carving operations (default 10000, the full workload)
#   EDGELAND_BENCH_CARVE_BUDGET_S wall seconds per peer's carving run (default 2400)
#   EDGELAND_BENCH_MEMORY_GB      address-space limit per benchmark process (default 12): the
#                                 machine is shared; a peer over it fails with bad_alloc
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=${EDGELAND_BENCH_BUILD_DIR:-$repo/build-bench}
out=${EDGELAND_BENCH_OUT:-$build/bench-results}
filter=${EDGELAND_BENCH_FILTER:-.}
limit=${EDGELAND_BENCH_TIMEOUT_S:-3600}
export EDGELAND_BENCH_CARVE_OPS=${EDGELAND_BENCH_CARVE_OPS:-10000}
export EDGELAND_BENCH_CARVE_BUDGET_S=${EDGELAND_BENCH_CARVE_BUDGET_S:-2400}
memory_kb=$(( ${EDGELAND_BENCH_MEMORY_GB:-12} * 1024 * 1024 ))

cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DEDGELAND_BUILD_BENCH=ON >&2
cmake --build "$build" --target edgeland_bench -j2 >&2
mkdir -p "$out"
rm -f "$out"/*.json
# Run a copy: a rebuild in the same tree during a long run must not mix two binaries.
bin=$out/edgeland_bench
cp "$build/bench/edgeland_bench" "$bin"
mapfile -t names < <("$bin" --benchmark_list_tests "--benchmark_filter=$filter")
for name in "${names[@]}"; do
  file=$out/${name//[\/:]/_}.json
  echo "running $name" >&2
  rc=0
  (ulimit -v "$memory_kb" && exec timeout "$limit" "$bin" "--benchmark_filter=^${name}\$" \
    --benchmark_format=json) >"$file" || rc=$?
  if [[ $rc -ne 0 ]]; then
    # Keep the failure as data: ratio_table.py shows it in the table.
    why=$([[ $rc -eq 124 ]] && echo "timeout after ${limit} s" || echo "exit code $rc")
    printf '{"failed": {"name": "%s", "why": "%s"}}\n' "$name" "$why" >"$file"
  fi
done
python3 "$repo/bench/ratio_table.py" "$out"
