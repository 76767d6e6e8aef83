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
#   EDGELAND_BENCH_PASSES         run every benchmark this many times and keep the fastest
#                                 (default 1); on a shared machine the minimum is the least
#                                 disturbed figure. Peers of one workload and size run back to
#                                 back, so their conditions are alike.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=${EDGELAND_BENCH_BUILD_DIR:-$repo/build-bench}
out=${EDGELAND_BENCH_OUT:-$build/bench-results}
filter=${EDGELAND_BENCH_FILTER:-.}
limit=${EDGELAND_BENCH_TIMEOUT_S:-3600}
export EDGELAND_BENCH_CARVE_OPS=${EDGELAND_BENCH_CARVE_OPS:-10000}
export EDGELAND_BENCH_CARVE_BUDGET_S=${EDGELAND_BENCH_CARVE_BUDGET_S:-2400}
memory_kb=$(( ${EDGELAND_BENCH_MEMORY_GB:-12} * 1024 * 1024 ))
passes=${EDGELAND_BENCH_PASSES:-1}

cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DEDGELAND_BUILD_BENCH=ON >&2
cmake --build "$build" --target edgeland_bench -j2 >&2
mkdir -p "$out"
rm -f "$out"/*.json
# Run a copy: a rebuild in the same tree during a long run must not mix two binaries.
bin=$out/edgeland_bench
cp "$build/bench/edgeland_bench" "$bin"
# Names are WORKLOAD/PEER/SIZE[/...]: ordered by workload, size, peer.
mapfile -t names < <("$bin" --benchmark_list_tests "--benchmark_filter=$filter" |
  awk -F/ '{print $1"/"$3"/"$2"/"$0}' | sort -t/ -k1,1 -k2,2n -k3,3 | cut -d/ -f4-)
cpu_time() {  # CPU time of a result file, or nothing for a failure
  python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["benchmarks"][0]["cpu_time"])' "$1" 2>/dev/null
}
for pass in $(seq 1 "$passes"); do
  for name in "${names[@]}"; do
    file=$out/${name//[\/:]/_}.json
    [[ -f $file ]] && grep -q '"failed"' "$file" && continue  # a failure is not retried
    echo "running $name (pass $pass of $passes)" >&2
    rc=0
    (ulimit -v "$memory_kb" && exec timeout "$limit" "$bin" "--benchmark_filter=^${name}\$" \
      --benchmark_format=json) >"$file.new" || rc=$?
    if [[ $rc -ne 0 ]]; then
      # Keep the failure as data: ratio_table.py shows it in the table.
      why=$([[ $rc -eq 124 ]] && echo "timeout after ${limit} s" || echo "exit code $rc")
      printf '{"failed": {"name": "%s", "why": "%s"}}\n' "$name" "$why" >"$file"
      rm -f "$file.new"
    elif [[ ! -f $file ]] || python3 -c 'import sys; sys.exit(0 if float(sys.argv[1]) < float(sys.argv[2]) else 1)' \
        "$(cpu_time "$file.new")" "$(cpu_time "$file")"; then
      mv "$file.new" "$file"
    else
      rm -f "$file.new"
    fi
  done
done
python3 "$repo/bench/ratio_table.py" "$out"
