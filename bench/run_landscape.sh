#!/usr/bin/env bash
# Builds edgeland_landscape_bench and plot_crossover (Release, in build/bench-landscape), runs
# every landscape benchmark in one process (JSON to BUILD/landscape-results/landscape.json),
# prints the Markdown tables of bench/README.md ("Landscape") and draws the crossover plot
# bench/landscape_crossover.png. About 10-20 minutes on the 2-core machine.
#
# Environment (all optional):
#   EDGELAND_LANDSCAPE_BUILD_DIR  build directory (default: build/bench-landscape)
#   EDGELAND_LANDSCAPE_FILTER     regex over benchmark names (default: everything)
#   EDGELAND_LANDSCAPE_PLOT       where the PNG goes (default: bench/landscape_crossover.png)
#   and the sizes the benchmark reads (bench/README.md, "Landscape"): EDGELAND_LANDSCAPE_EDITS,
#   _BLOCK, _REPEATS, _QUERIES, _CAVES, _SCALING_AREA, _SCALING_TIMED, _CROSSOVER_REPS,
#   _SNAPSHOTS.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=${EDGELAND_LANDSCAPE_BUILD_DIR:-$repo/build/bench-landscape}
filter=${EDGELAND_LANDSCAPE_FILTER:-.}
plot=${EDGELAND_LANDSCAPE_PLOT:-$repo/bench/landscape_crossover.png}
out=$build/landscape-results

cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DEDGELAND_BUILD_BENCH=ON \
  -DEDGELAND_BUILD_TESTS=OFF -DEDGELAND_BUILD_PROOFS=OFF >&2
cmake --build "$build" --target edgeland_landscape_bench plot_crossover -j2 >&2
mkdir -p "$out"
# Run a copy: a rebuild in the same tree during the run must not mix two binaries.
cp "$build/bench/edgeland_landscape_bench" "$out/"
"$out/edgeland_landscape_bench" "--benchmark_filter=$filter" \
  "--benchmark_out=$out/landscape.json" --benchmark_out_format=json >&2
python3 "$repo/bench/landscape_tables.py" "$out/landscape.json" "$out/crossover.tsv" | tee "$out/tables.md"
if [[ $(grep -c '^[0-9]' "$out/crossover.tsv") -ge 2 ]]; then
  "$build/bench/plot_crossover" "$out/crossover.tsv" "$plot"
  echo "plot: $plot" >&2
fi
