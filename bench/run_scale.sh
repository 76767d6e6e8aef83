#!/usr/bin/env bash
# Builds edgeland_scale_bench (Release), runs every benchmark in its own process, one at a
# time, under a wall-clock limit, and prints the Markdown table of bench/README.md, "Scale:
# many crossings, large inputs" (scale_table.py). A peer over the limit is killed and shown
# as "> limit" with the peak memory it had reached; it is not run on the larger sizes of that
# shape (they are shown as skipped), since the time only grows with the size.
#
# Environment (all optional):
#   EDGELAND_BENCH_BUILD_DIR  build directory (default: build-bench in the repository)
#   EDGELAND_SCALE_OUT        where the JSON files go (default: BUILD_DIR/scale-results)
#   EDGELAND_SCALE_FILTER     regex over benchmark names SHAPE/PEER/SIZE (default: everything)
#   EDGELAND_SCALE_TIMEOUT_S  wall-clock limit per benchmark process (default 300)
#   EDGELAND_SCALE_KEEP       1: keep earlier result files and run only what has none (resume)
#   EDGELAND_BENCH_MEMORY_GB  address-space limit per process (default 12): the machine is
#                             shared; a peer over it fails with bad_alloc ("threw" in the table)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=${EDGELAND_BENCH_BUILD_DIR:-$repo/build-bench}
out=${EDGELAND_SCALE_OUT:-$build/scale-results}
filter=${EDGELAND_SCALE_FILTER:-.}
limit=${EDGELAND_SCALE_TIMEOUT_S:-300}
memory_kb=$(( ${EDGELAND_BENCH_MEMORY_GB:-12} * 1024 * 1024 ))

cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DEDGELAND_BUILD_BENCH=ON >&2
cmake --build "$build" --target edgeland_scale_bench -j2 >&2
mkdir -p "$out"
[[ ${EDGELAND_SCALE_KEEP:-0} == 1 ]] || rm -f "$out"/*.json
# Run a copy: a rebuild in the same tree during a long run must not mix two binaries.
bin=$out/edgeland_scale_bench
cp "$build/bench/edgeland_scale_bench" "$bin"
# What was measured: the table's header says which commit, and whether the tree was dirty.
python3 - "$out/meta.json" "$limit" "$(git -C "$repo" rev-parse --short HEAD)" \
  "$(git -C "$repo" status --porcelain -- kernel clip spatial | wc -l)" <<'EOF'
import datetime, json, sys
json.dump({"limit_s": int(sys.argv[2]), "commit": sys.argv[3], "dirty_files": int(sys.argv[4]),
           "date": datetime.date.today().isoformat()}, open(sys.argv[1], "w"))
EOF

# Names are SHAPE/PEER/SIZE/iterations:1: ordered by shape (as registered), size, peer.
mapfile -t names < <("$bin" --benchmark_list_tests "--benchmark_filter=$filter" |
  awk -F/ '!($1 in s) { s[$1] = ++k } { print s[$1] "/" $3 "/" $0 }' |
  sort -s -t/ -k1,1n -k2,2n | cut -d/ -f3-)

failed() {  # failed FILE NAME WHY [EXTRA-JSON]: a failure kept as data for the table
  printf '{"failed": {"name": "%s", "why": "%s"%s}}\n' "$2" "$3" "${4:-}" >"$1"
}

# run_one NAME FILE: the benchmark in its own process; past the limit it is killed, after
# reading its peak resident set (VmHWM), which dies with it.
run_one() {
  local name=$1 file=$2 pid start hwm_kb="" rc=0
  (ulimit -v "$memory_kb" && exec "$bin" "--benchmark_filter=^${name}\$" \
    --benchmark_format=json) >"$file.new" 2>"$file.err" &
  pid=$!
  start=$SECONDS
  while kill -0 "$pid" 2>/dev/null; do
    if (( SECONDS - start >= limit )); then
      hwm_kb=$(awk '/^VmHWM/ { print $2 }' "/proc/$pid/status" 2>/dev/null || true)
      kill "$pid" 2>/dev/null || true
      break
    fi
    sleep 1
  done
  wait "$pid" || rc=$?
  if [[ -n $hwm_kb ]]; then
    failed "$file" "$name" timeout ", \"limit_s\": $limit, \"rss_peak_mb\": $(( hwm_kb / 1024 ))"
  elif [[ $rc -ne 0 ]]; then
    failed "$file" "$name" "exit code $rc: $(tail -n 1 "$file.err" | tr -d '"\\')"
  else
    mv "$file.new" "$file"
  fi
  rm -f "$file.new" "$file.err"
}

declare -A over_limit  # SHAPE/PEER -> the size at which it timed out
for name in "${names[@]}"; do
  IFS=/ read -r shape peer size _ <<<"$name"
  file=$out/${name//[\/:]/_}.json
  if [[ -f $file ]]; then :  # kept from an earlier run (EDGELAND_SCALE_KEEP=1)
  elif [[ -n ${over_limit[$shape/$peer]:-} ]]; then
    failed "$file" "$name" skipped ", \"limit_s\": $limit, \"after\": ${over_limit[$shape/$peer]}"
  else
    echo "running $name ($(date +%H:%M:%S))" >&2
    run_one "$name" "$file"
  fi
  if grep -q '"why": "timeout"' "$file"; then over_limit[$shape/$peer]=$size; fi
done
python3 "$repo/bench/scale_table.py" "$out"
